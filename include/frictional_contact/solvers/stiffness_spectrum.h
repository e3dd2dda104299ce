#pragma once

#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <frictional_contact/solvers/stiffness_operator.h>
#include <frictional_contact/solvers/shifted_stiffness_solver.h>

namespace FrictionalContact
{
  /**
   * The smallest eigenvalue of K (the paper's mu_pi, the strong convexity
   * modulus of the elastic energy), by PARPACK's implicitly restarted
   * Lanczos method in shift-invert mode (shift 0): each Lanczos step is one
   * AMG-preconditioned CG solve with K, as Matlab's eigs(K, 1,
   * 'smallestabs') in the paper.
   */
  struct SmallestEigenvalue
  {
    double       value         = 0;
    /// Rayleigh quotient of the returned eigenvector, a check on value.
    double       rayleigh_quotient = 0;
    unsigned int n_solves      = 0;
    unsigned int cg_iterations = 0;
  };

  /**
   * Computes mu_pi to the relative @p tolerance, with @p n_lanczos_vectors
   * Lanczos vectors. @p solver must have been initialized with @p stiffness.
   */
  SmallestEigenvalue
  compute_smallest_eigenvalue(const StiffnessOperator &stiffness,
                              ShiftedStiffnessSolver               &solver,
                              const double                          tolerance,
                              const unsigned int n_lanczos_vectors);
} // namespace FrictionalContact
