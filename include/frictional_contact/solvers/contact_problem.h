#pragma once

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <frictional_contact/solvers/contact_map.h>
#include <frictional_contact/solvers/iterate_geometry.h>
#include <frictional_contact/solvers/nonlinear_stiffness.h>
#include <frictional_contact/solvers/stiffness_operator.h>

#include <cstdint>
#include <string>
#include <vector>

namespace FrictionalContact
{
  /**
   * The bodies of a problem that only contact holds against rigid-body
   * motion: K is singular on them until contact nodes hold them. The
   * semismooth Newton method starts with their nodes nearest to contact
   * active, stops with a clear message where an iteration leaves such a
   * body no contact node, and adds S to its Newton matrices (not to the
   * residual: S changes the steps, not the solution).
   */
  struct ContactHeldBodies
  {
    /// At most this many bodies (the bits of held_by_candidate).
    static constexpr unsigned int max_bodies = 64;
    /// S = stabilization_factor diag(K) at the dofs of these bodies: small
    /// against K where contact holds the body (the Newton steps converge as
    /// without), finite where it does not yet (a rotation about the one
    /// node a ball touches).
    static constexpr double stabilization_factor = 1e-8;

    std::vector<std::string> names;
    /// For each local candidate, the bodies it holds when it is in contact
    /// (bit k: names[k]).
    std::vector<std::uint64_t> held_by_candidate;
    /// S as a vector of its diagonal (locally owned entries); empty if
    /// there are no such bodies.
    TrilinosWrappers::MPI::Vector stabilization;

    bool
    any() const
    {
      return !names.empty();
    }
  };



  /// The normal component n that, with the tangential components u_t of
  /// @p u, closes a gap @p gap that changes along the slide by @p slope:
  /// n - slope . (n, u_t) = gap (IncrementalProblem::gap_at()).
  template <int dim>
  inline double
  normal_closing_gap(const Tensor<1, dim> &slope, Tensor<1, dim> u, const double gap)
  {
    u[0] = 0;
    return (gap + slope * u) / (1. - slope[0]);
  }



  /**
   * One incremental problem of the paper, eq. (9): find du and r with
   * K du - p = T r and the cone complementarity at every candidate, where
   * the displacement of node j relative to the obstacle is
   * T_j^T du - obstacle_slip[j]. For bodies of nonlinear laws, K du is
   * N(du) (NonlinearStiffness) and K its tangent.
   */
  template <int dim>
  struct IncrementalProblem
  {
    /// The problem with K, p and T; the other members are set afterwards.
    IncrementalProblem(const StiffnessOperator &stiffness,
                       const TrilinosWrappers::MPI::Vector  &load,
                       const ContactMap<dim>                &contact)
      : stiffness(stiffness)
      , load(load)
      , contact(contact)
    {}

    /// K, or the tangent K_T of the last evaluation of @p nonlinear.
    const StiffnessOperator &stiffness;
    /// p = p^{l+1} - K u^l (zero at fixed dofs).
    const TrilinosWrappers::MPI::Vector &load;
    const ContactMap<dim>               &contact;
    /// A length of the increment (largest gap, displacement or elastic
    /// displacement increment) for tolerances that follow the units.
    double length_scale = 1;
    /// The paper's sigma_T and mu_pi.
    double largest_singular_value_T = 1;
    double smallest_eigenvalue_K    = 0;
    /// g_j: the gap of candidate j before the increment, with the obstacle
    /// already at its position at the end of the increment.
    std::vector<double> gaps;
    /// The prescribed displacement increment of what j touches (the
    /// obstacle, or a rigid tool) in the frame of j, tangential components
    /// only (component 0 is zero: the gap has it).
    std::vector<Tensor<1, dim>> obstacle_slip;
    /// Where a pair's mortar rows follow the Newton iterates: how each
    /// node's gap changes as it moves relative to its master, in its
    /// frame: the row's slide along the master (empty elsewhere; see
    /// gap_at()).
    std::vector<Tensor<1, dim>> gap_slopes;
    /// Where a candidate touches a deformable body (a pair's slave node),
    /// the normal stiffness of that body seen at the node
    /// (MortarBasis::master_stiffness()); empty where every candidate
    /// touches something rigid (an obstacle, a tool).
    std::vector<double> master_stiffness;
    /// The bodies only contact holds (none for most scenes).
    ContactHeldBodies contact_held;
    /// The internal force of nonlinear laws (nullptr: K du).
    NonlinearStiffness *nonlinear = nullptr;
    /// A looser stopping tolerance for this solve than the method's (a
    /// pass of the pairs' geometry that is not the last); 0: the
    /// method's. The semismooth Newton method takes it, the others keep
    /// their own.
    double tolerance = 0;
    /// Where the frames follow the configuration (finite strain against a
    /// curved obstacle, or contact pairs): the geometry the Newton method
    /// takes at each iterate. Null for fixed frames.
    IterateGeometry<dim> *geometry = nullptr;

    /// K du, or N(du) for nonlinear laws (then with @p with_tangent also
    /// the tangent at du as the stiffness).
    void
    internal_force(const TrilinosWrappers::MPI::Vector &du,
                   TrilinosWrappers::MPI::Vector       &dst,
                   const bool                           with_tangent = false) const
    {
      if (nonlinear != nullptr)
        nonlinear->internal_force_change(du, dst, with_tangent);
      else
        stiffness.vmult(dst, du);
    }

    /// (t_n,j^T du, T_t,j^T du - obstacle's tangential motion)
    Tensor<1, dim>
    relative_displacement(const unsigned int j,
                          const TrilinosWrappers::MPI::Vector &du) const
    {
      return contact.local_part(j, du) - obstacle_slip[j];
    }

    /// Node j's gap at the relative displacement @p u_j: g_j less its
    /// normal component, and plus the gap's change as the node slides
    /// along a master whose rows follow the iterates (gap_slopes).
    double
    gap_at(const unsigned int j, const Tensor<1, dim> &u_j) const
    {
      return gaps[j] - (gap_slopes.empty() ? u_j[0] : u_j[0] - gap_slopes[j] * u_j);
    }

    /// The normal component that closes node j's gap exactly
    /// (gap_at() = 0) with the tangential components of @p u_j.
    double
    closing_normal(const unsigned int j, const Tensor<1, dim> &u_j) const
    {
      return gap_slopes.empty() ? gaps[j] : normal_closing_gap(gap_slopes[j], u_j, gaps[j]);
    }
  };

  /// The paper's three residuals, eqs. (24)-(26).
  struct Residuals
  {
    /// |K du - p - T r|
    double force_balance = 0;
    /// |sum_j <(-g_j - mu |T_t,j^T du| + t_n,j^T du, T_t,j^T du), r_j>|
    double complementarity = 0;
    /// |min(g - T_n^T du, 0)|
    double penetration = 0;

    bool
    finite() const
    {
      return std::isfinite(force_balance) && std::isfinite(complementarity) &&
             std::isfinite(penetration);
    }
  };

  /**
   * The residuals at (du, r), given K du and T r (which the solvers have at
   * hand). @p scratch is a work vector of the size of du.
   */
  /**
   * The scale c_j of the complementarity functions at each candidate: the
   * normal stiffness of node j against what it touches. That is its own,
   * @p own (ContactMap::normal_stiffness() of K), where it touches
   * something rigid, and where it touches another body the two in series,
   * c_j = k_j m_j / (k_j + m_j) with m_j the problem's master_stiffness:
   * the slave's alone was the stiffer side's where the slave is much
   * stiffer than its master, and c_j that large let the tiny slips of
   * inexact Newton steps decide the stick and slip sets (doc/algorithm.md,
   * "Bodies of very different stiffness").
   */
  template <int dim>
  std::vector<double>
  contact_stiffness(const IncrementalProblem<dim> &problem, std::vector<double> own);

  template <int dim>
  Residuals
  compute_residuals(const IncrementalProblem<dim>     &problem,
                    const TrilinosWrappers::MPI::Vector &du,
                    const TrilinosWrappers::MPI::Vector &K_du,
                    const TrilinosWrappers::MPI::Vector &T_r,
                    const std::vector<Tensor<1, dim>>   &r,
                    TrilinosWrappers::MPI::Vector       &scratch);

  /**
   * Where the iterate du is worst, for the line of a solve that failed:
   * the deepest penetration and the node it is at (in the reference
   * configuration), and for nonlinear laws what they name (the smallest
   * det F and its cell); empty where nothing penetrates by more than
   * round-off (1e-12 of the length scale) and the laws name nothing.
   * Collective.
   */
  template <int dim>
  std::string
  worst_places(const IncrementalProblem<dim> &problem, const TrilinosWrappers::MPI::Vector &du);

  /// One row of a convergence history: one iteration of the contact solver.
  struct HistoryRow
  {
    unsigned int iteration;
    double       seconds;
    Residuals    residuals;
    double       step;
    /// Krylov (CG or GMRES) iterations of the iteration's linear solves.
    unsigned int linear_iterations;
    /// Candidates whose free/stick/slip condition changed (Newton; 0 for
    /// Algorithm 2, which has no active sets).
    unsigned int active_set_changes;
    /// The factor the Krylov solver reduced its residual by (Newton's
    /// forcing term; 0 for Algorithm 2).
    double forcing_term;
    /// Candidates in contact (stick or slip) and quadrature points that
    /// flow plastically in the iteration (Newton; 0 for Algorithm 2).
    types::global_dof_index active_nodes   = 0;
    types::global_dof_index plastic_points = 0;
  };

  /// What a contact solve reports, whatever the method.
  struct SolveStatistics
  {
    bool         converged      = false;
    unsigned int iterations     = 0;
    /// Krylov (CG or GMRES) iterations of all linear solves.
    unsigned int linear_iterations = 0;
    unsigned int amg_setups     = 0;
    /// Updates of the AMG for new node conditions (Newton): its coarse
    /// levels made again, not a set-up.
    unsigned int amg_updates    = 0;
    double       seconds        = 0;
    double       last_step      = 0;
    /// Whether it stopped at IncrementalProblem::tolerance, looser than
    /// the method's.
    bool         loosened       = false;
    Residuals    residuals;
    /// Why the solve stopped, if it did not converge, and where its last
    /// iterate is worst (worst_places()).
    std::string  failure;
    std::string  worst_places;
    /// One row per iteration, if recording was asked for.
    std::vector<HistoryRow> history;

    /// Adds the work of another solve of the same increment (its
    /// iterations, set-ups and time).
    void
    add_work(const SolveStatistics &more)
    {
      iterations += more.iterations;
      linear_iterations += more.linear_iterations;
      amg_setups += more.amg_setups;
      amg_updates += more.amg_updates;
      seconds += more.seconds;
    }
  };
} // namespace FrictionalContact
