#include <frictional_contact/base/plugins.h>
#include <frictional_contact/postprocess/interface.h>

namespace FrictionalContact
{
  namespace Postprocess
  {
    /// The columns of the displacement and its increment, and at finite
    /// strain the smallest det F.
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
        Columns columns{{"Max displacement magnitude",
                         body.largest_nodal_magnitude(result.state.u),
                         true},
                        {"Max displacement increment magnitude",
                         body.largest_nodal_magnitude(result.outcome.du),
                         true}};
        const BodyResponse<dim> &response = result.model.get_response();
        if (response.finite_strain())
          {
            TrilinosWrappers::MPI::Vector u = body.make_ghosted_vector();
            u                               = result.state.u;
            columns.push_back(
              {"Smallest det F", response.smallest_jacobian(u).value, true});
          }
        return columns;
      }
    };

    FRICTIONAL_CONTACT_REGISTER_PLUGIN(
      Interface,
      DisplacementStatistics,
      "displacement statistics",
      "Statistics columns of the displacement: the largest nodal magnitude "
      "|u| of the displacement and of the increment's du; at finite strain "
      "the smallest det F at the quadrature points and the cells' corners "
      "(a cell that folds shows it first).")
  } // namespace Postprocess
} // namespace FrictionalContact
