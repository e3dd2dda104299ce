#pragma once

#include <deal.II/base/parameter_handler.h>

#include <frictional_contact/driver/increment_solver.h>
#include <frictional_contact/model/model.h>

#include <functional>

namespace FrictionalContact
{
  /**
   * The contact pairs' geometry over an increment; owns the subsection
   * <Contact/Pair geometry>. The mortar data of every pair (normals, rows
   * P, gaps) is taken where the increment starts. A pair with a body at
   * finite strain moves within the increment, so its data is then taken
   * again where the solve ended (the gaps still measured at the start)
   * and the increment solved again, until the normals and gaps settle: a
   * fixed point on the geometry, its passes and last change reported with
   * the increment.
   */
  template <int dim>
  class PairGeometry
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    explicit PairGeometry(ParameterHandler &prm);

    /**
     * Solves the increment from @p t_start to @p t_end of a state with
     * displacement @p u by @p solve_once (from a warm start, or none for
     * the first solve), with the pairs' data taken as above. An increment whose geometry does not settle in <Maximum
     * passes> comes back not converged, saying so. Collective.
     */
    IncrementOutcome<dim>
    solve(Model<dim>                          &model,
          const TrilinosWrappers::MPI::Vector &u,
          const double                         t_start,
          const double                         t_end,
          const std::function<IncrementOutcome<dim>(const WarmStart<dim> *)>
            &solve_once) const;

  private:
    /// The largest change of a unit normal, and of a gap over the
    /// largest displacement where the increment ended, that counts as settled.
    double       tolerance;
    unsigned int max_passes;
  };
} // namespace FrictionalContact
