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
      Columns
      execute(const IncrementResult<dim> &result) override
      {
        return {{"Max displacement", result.state.u.linfty_norm(), true},
                {"Max displacement increment",
                 result.outcome.du.linfty_norm(),
                 true}};
      }
    };

    FRICTIONAL_CONTACT_REGISTER_PLUGIN(
      Interface,
      DisplacementStatistics,
      "displacement statistics",
      "Statistics columns of the displacement: the largest component of u "
      "and of the increment's du.")
  } // namespace Postprocess
} // namespace FrictionalContact
