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

    /**
     * 10: the shipped block_on_block_2d (pressed, then dragged until it
     * slides) reaches the tolerance with the block 10 times stiffer than
     * the base; at 100 its steps stall at 2e-14 against a tolerance of
     * 1.2e-14 in increment 6, at 1e3 at 4.6e-13 against 8e-15 in
     * increment 5, at 1e5 in increment 2 (round-off of the stiff body's
     * forces in the steps; doc/algorithm.md, "Bodies of very different
     * stiffness").
     */
    double
    largest_modulus_ratio() const override
    {
      return 10;
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
