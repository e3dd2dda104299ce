#pragma once

#include <frictional_contact/solvers/contact_solver.h>

namespace FrictionalContact
{
  /**
   * A semismooth Newton (primal-dual active set) method for the incremental
   * problem, in the style of Hueber, Stadler and Wohlmuth (SIAM J. Sci.
   * Comput. 30, 2008), for nodal contact with a rigid obstacle. Each
   * iteration sorts the candidates by the augmented reactions
   * sigma_j = -r_n - c_j (g_j - u_n) and zeta_j = r_t - c_j u_t into free
   * (sigma <= 0), stick (|zeta| < mu sigma) and slip, and solves one linear
   * elastic problem: free nodes unloaded, the normal displacement of active
   * nodes fixed to the gap, the tangential displacement of sticking nodes
   * fixed, and the friction force mu sigma zeta/|zeta| applied at slipping
   * nodes (the friction bound lagged by one iteration, which keeps the
   * system symmetric positive definite). The constraints are imposed by
   * projection inside CG, preconditioned with the AMG of K, so the
   * preconditioner is built once. c_j is the normal stiffness of node j,
   * t_n,j^T K t_n,j: the method does not depend on the units. The reactions
   * are the residual K du - p at the active nodes.
   */
  template <int dim>
  class SemismoothNewtonSolver : public ContactSolver<dim>
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm) override;

    std::string
    describe() const override;

    std::string
    iteration_name() const override
    {
      return "Newton";
    }

    SolveStatistics
    solve(const IncrementalProblem<dim> &problem,
          ShiftedStiffnessSolver        &linear_solver,
          Vector                        &du,
          std::vector<Tensor<1, dim>>   &r,
          const bool                     record_history) const override;

  private:
    double       tolerance;
    unsigned int max_iterations;
    double       linear_reduction;
    double       tangential_factor;
  };
} // namespace FrictionalContact
