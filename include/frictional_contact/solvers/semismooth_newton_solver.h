#pragma once

#include <frictional_contact/solvers/contact_solver.h>
#include <frictional_contact/solvers/forcing_term.h>

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
   * fixed, and at slipping nodes the friction force coupled to the normal
   * reaction, r_t = -mu r_n zeta/|zeta|, with (in 3D) a Robin term across
   * the slip direction: the linearisation of r_t = mu |r_n| zeta/|zeta|.
   * The constraints are imposed by projection inside CG (GMRES(50) when a
   * node slips, since the coupling makes the system non-symmetric),
   * preconditioned with the AMG of K with the node conditions as springs
   * (ConditionPreconditioner; or Jacobi, as <Linear solver/
   * Preconditioner> says), to the accuracy of a ForcingTerm.
   * A line search on the complementarity functions and the force balance
   * keeps the sets from cycling. c_j is the normal stiffness of node j,
   * t_n,j^T K t_n,j: the method does not depend on the units. The
   * reactions are the residual K du - p at the active nodes. It needs a
   * ContactMap whose T_j are orthonormal on disjoint entries (one node
   * each).
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

    /// No: the first Newton iteration is an elastic solve, and a body
    /// that touches nothing converges with every node free.
    bool
    wants_elastic_trial() const override
    {
      return false;
    }

    /// Yes: a start within the region of fast convergence saves steps.
    bool
    gains_from_last_increment_start() const override
    {
      return true;
    }

    /// Yes: each step evaluates the internal force and its tangent.
    bool
    handles_nonlinear_laws() const override
    {
      return true;
    }

    /// Yes: it starts from the nodes nearest to contact and stabilises
    /// the Newton matrices (ContactHeldBodies).
    bool
    handles_contact_held_bodies() const override
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
    double            linear_reduction;
    ForcingTerm::Rule forcing_rule;
    double            tangential_factor;
    bool              preconditioner_sees_conditions;
  };
} // namespace FrictionalContact
