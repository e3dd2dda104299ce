#include <frictional_contact/base/plugins.h>
#include <frictional_contact/postprocess/interface.h>

namespace FrictionalContact
{
  namespace Postprocess
  {
    /// The columns of the force the prescribed boundaries exert on the
    /// body (a tensile test's load), when it has any.
    template <int dim>
    class SupportStatistics : public Interface<dim>
    {
    public:
      unsigned int
      default_position() const override
      {
        // After the displacement's columns; the visualization shares 4
        // and, adding no columns, comes after it by name.
        return 4;
      }

      Columns
      execute(const IncrementResult<dim> &result) override
      {
        const ElasticBody<dim> &body = result.model.get_body();
        if (!body.has_prescribed_boundaries())
          return {};
        TrilinosWrappers::MPI::Vector u = body.make_ghosted_vector();
        u                               = result.state.u;
        // The reaction: the force the prescribed boundaries exert on the
        // body (positive along +x when they pull it that way).
        const Tensor<1, dim> reaction =
          result.model.support_reaction(u, result.load_factor, Supports::prescribed);
        Columns columns;
        for (unsigned int c = 0; c < dim; ++c)
          columns.push_back({std::string("Prescribed boundary force ") + "xyz"[c],
                             reaction[c],
                             true});
        return columns;
      }
    };

    FRICTIONAL_CONTACT_REGISTER_PLUGIN(
      Interface,
      SupportStatistics,
      "support statistics",
      "Statistics columns of the supports, when a boundary is prescribed "
      "(<Boundary conditions/Prescribed boundaries>): the force the "
      "prescribed boundaries exert on the body, its components x, y (and "
      "z), summed over their nodes (the load of a tensile test).")
  } // namespace Postprocess
} // namespace FrictionalContact
