#pragma once

#include <frictional_contact/fclib/fclib_problem.h>

#include <string>

namespace FrictionalContact
{
  /**
   * The semismooth Newton method for an FCLIB global problem with any
   * sparse M (also non-symmetric) and H: Alart and Curnier's formulation
   * (Comput. Methods Appl. Mech. Engrg. 92, 1991) on (v, r),
   *
   *   M v - H r - f = 0,
   *   r_n - max(0, z_n) = 0,                         z_n = r_n - rho_c u_n,
   *   r_t - P_B(mu max(0, z_n))(z_t) = 0,            z_t = r_t - rho_c u_t,
   *
   * with u = H^T v + w and P_B(R) the projection onto the disc of radius R;
   * its solutions are those of FCLIB's problem. With few contact unknowns
   * (m <= 400) v is eliminated through one LU of M and each step solves a
   * dense m x m system (CondensedSystem); otherwise each step factorises the
   * whole sparse Jacobian (CoupledSystem). A small proximal term keeps the
   * steps defined where the reactions are not unique; a non-monotone
   * backtracking line search on |F|^2 globalises the method. It stops when
   * FCLIB's error (fclib_error) is at most the tolerance.
   */
  class FclibNewton
  {
  public:
    struct Result
    {
      bool          converged  = false;
      unsigned int  iterations = 0;
      double        seconds    = 0;
      double        error      = 0;
      /// Why it did not converge (empty if it did).
      std::string   failure;
      FclibSolution solution;
    };

    explicit FclibNewton(const FclibProblem &problem);

    /// Solves from v = 0, r = 0.
    Result
    solve(const double tolerance, const unsigned int max_iterations) const;

  private:
    const FclibProblem &problem;
  };
} // namespace FrictionalContact
