#pragma once

#include <frictional_contact/solvers/contact_solver.h>

namespace FrictionalContact
{
  /**
   * Kanno's accelerated primal-dual method (Algorithm 2 of the paper) for
   * one incremental problem, with the projection onto the friction cone of
   * Algorithm 3 and the update of the modified gap
   * g~_j = g_j + mu |T_t,j^T du|. Each primal step solves
   * (beta_k K + I) du_{k+1} = b with CG, warm-started from du_k: it solves
   * for the step du_{k+1} - du_k, whose right-hand side is
   * beta_k (p + T r_{k+1} - K du_k), which is the same thing. Stops when
   * |du_{k+1} - du_k| <= tolerance, as the paper.
   */
  template <int dim>
  class PrimalDualSolver : public ContactSolver<dim>
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    /// Declares the entries of its subsection of "Contact solver".
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm) override;

    std::string
    describe() const override;

    std::string
    iteration_name() const override
    {
      return "primal-dual";
    }

    bool
    needs_smallest_eigenvalue() const override
    {
      return true;
    }

    SolveStatistics
    solve(const IncrementalProblem<dim> &problem,
          ShiftedStiffnessSolver        &linear_solver,
          Vector                        &du,
          std::vector<Tensor<1, dim>>   &r,
          const bool                     record_history) const override;

  private:
    double       initial_alpha;
    bool         paper_scaling;
    double       step_tolerance;
    /// Whether CG starts a step from the extrapolation of the last two.
    bool         extrapolate_start;
    unsigned int stagnation_window;
  };
} // namespace FrictionalContact
