#include <frictional_contact/base/plugins.h>
#include <frictional_contact/postprocess/interface.h>

namespace FrictionalContact
{
  namespace Postprocess
  {
    /// The columns of the displacement and its increment.
    template <int dim>
    class DisplacementStatistics : public Interface<dim>
    {
    public:
      unsigned int
      default_position() const override
      {
        return 3;
      }

      Columns
      execute(const IncrementResult<dim> &result) override
      {
        const ElasticBody<dim> &body = result.model.get_body();
        return {{"Max displacement magnitude",
                 body.largest_nodal_magnitude(result.state.u),
                 true},
                {"Max displacement increment magnitude",
                 body.largest_nodal_magnitude(result.outcome.du),
                 true}};
      }
    };

    FRICTIONAL_CONTACT_REGISTER_PLUGIN(
      Interface,
      DisplacementStatistics,
      "displacement statistics",
      "Statistics columns of the displacement: the largest nodal magnitude "
      "|u| of the displacement and of the increment's du.")
  } // namespace Postprocess
} // namespace FrictionalContact
