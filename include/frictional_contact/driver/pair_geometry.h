#pragma once

#include <frictional_contact/driver/increment_solver.h>
#include <frictional_contact/model/model.h>

#include <functional>

namespace FrictionalContact
{
  /**
   * Solves the increment from @p t_start to @p t_end of a state with
   * displacement @p u by @p solve_once (from a warm start, or none for the
   * first solve), with the contact pairs' geometry settled. The mortar
   * data of every pair (normals, rows P, gaps) is taken where the
   * increment starts. A pair with a body at finite strain whose geometry
   * is not taken within Newton moves within the increment, so its data is
   * then taken again where the solve ended (the gaps still measured at the
   * start) and the increment solved again, until the normals and gaps
   * settle (ContactOperator::pair_passes_settings(), <Contact/Pair
   * geometry>): a fixed point on the geometry, accelerated by Anderson's
   * mixing, its passes and last change reported with the increment. An
   * increment whose geometry does not settle in <Maximum passes> comes
   * back not converged, saying so. Collective.
   */
  template <int dim>
  IncrementOutcome<dim>
  solve_with_settled_pair_geometry(
    Model<dim>                          &model,
    const TrilinosWrappers::MPI::Vector &u,
    const double                         t_start,
    const double                         t_end,
    const std::function<IncrementOutcome<dim>(const WarmStart<dim> *)> &solve_once);
} // namespace FrictionalContact
