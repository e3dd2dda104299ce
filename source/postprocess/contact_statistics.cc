#include <frictional_contact/base/plugins.h>
#include <frictional_contact/postprocess/interface.h>

namespace FrictionalContact
{
  namespace Postprocess
  {
    /// The columns of the contact state: node counts, forces and areas.
    template <int dim>
    class ContactStatistics : public Interface<dim>
    {
    public:
      unsigned int
      default_position() const override
      {
        return 2;
      }

      Columns
      execute(const IncrementResult<dim> &result) override
      {
        const ContactSummary<dim> &s = result.summary;
        Columns columns = {
          {"Free nodes", std::uint64_t(s.count(ContactState::free))},
          {"Stick nodes", std::uint64_t(s.count(ContactState::stick))},
          {"Slip nodes", std::uint64_t(s.count(ContactState::slip))}};
        // x, y and z in 2D too, so that the columns are the same.
        for (unsigned int d = 0; d < 3; ++d)
          columns.push_back({std::string("Contact force ") + "xyz"[d],
                             d < dim ? s.force[d] : 0.,
                             true});
        columns.push_back({"Normal contact force", s.normal_force, true});
        columns.push_back({"Tangential contact force", s.tangential_force, true});
        columns.push_back({"Contact area", s.contact_area, true});
        columns.push_back({"Stick area", s.stick_area, true});
        columns.push_back({"Max contact pressure", s.max_pressure, true});
        columns.push_back(
          {"Max boundary penetration", s.deepest_penetration, true});
        return columns;
      }
    };

    FRICTIONAL_CONTACT_REGISTER_PLUGIN(
      Interface,
      ContactStatistics,
      "contact statistics",
      "Statistics columns of the contact: free, stick and slip nodes, the "
      "total contact force and its normal and tangential parts, the contact "
      "and stick areas, the largest contact pressure, and the deepest "
      "penetration of any vertex of the contact boundaries (candidate or "
      "not) into the obstacle.")
  } // namespace Postprocess
} // namespace FrictionalContact
