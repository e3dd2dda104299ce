#pragma once

#include <string>
#include <vector>

namespace FrictionalContact
{
  /// One entry of a sparse matrix.
  struct MatrixEntry
  {
    unsigned int row;
    unsigned int column;
    double       value;
  };

  /**
   * A global frictional contact problem as FCLIB stores it, in FCLIB's own
   * sign convention (doc/fclib.md): find v, u, r with
   *
   *   M v = H r + f,  u = H^T v + w,
   *   K_mu* ∋ (u_n + mu |u_t|, u_t) ⟂ r ∈ K_mu = {|r_t| <= mu r_n}
   *
   * per contact (normal component first). Owns plain copies of the arrays
   * (n = size of v, m = spacedim times the number of contacts); the
   * exchange with HDF5 files goes through libfclib.
   */
  struct FclibProblem
  {
    unsigned int             spacedim = 3;
    unsigned int             n        = 0;
    std::vector<MatrixEntry> M;
    std::vector<MatrixEntry> H;
    std::vector<double>      f;
    std::vector<double>      w;
    std::vector<double>      mu;
    std::string              title;
    std::string              description;

    unsigned int
    n_contacts() const
    {
      return mu.size();
    }
  };

  /// A solution in FCLIB's convention: v (size n), u and r (size m).
  struct FclibSolution
  {
    std::vector<double> v;
    std::vector<double> u;
    std::vector<double> r;
  };

  /**
   * Reads the global problem of the FCLIB file @p path with libfclib and
   * checks it: sizes, finite values, no equality constraints (G), one
   * friction coefficient. Throws an InputError naming
   * the file and what is wrong.
   */
  FclibProblem
  read_fclib_problem(const std::string &path);

  /// Reads the solution stored in @p path for @p problem (InputError if
  /// there is none or its sizes do not fit).
  FclibSolution
  read_fclib_solution(const std::string &path, const FclibProblem &problem);

  /**
   * Writes @p problem, and @p solution if it is not null, to @p path with
   * libfclib (creating its folder if needed). The file is written under a temporary name and renamed at the
   * end, so an existing file is replaced only by a complete one.
   */
  void
  write_fclib(const std::string   &path,
              const FclibProblem  &problem,
              const FclibSolution *solution);

  /**
   * max |a_ij - a_ji| / sqrt(|a_ii a_jj|) over the entries of @p A
   * (duplicates summed): its asymmetry relative to the diagonal, which
   * does not change when rows and columns are scaled (M of an LMGC90
   * file mixes entries of 1e8 with entries of 1).
   */
  double
  asymmetry(const std::vector<MatrixEntry> &A);

  /// The asymmetry() up to which a matrix counts as symmetric (the
  /// round-off of a symmetric assembly).
  constexpr double largest_symmetric_asymmetry = 1e-10;

  /// u = H^T v + w.
  std::vector<double>
  local_velocity(const FclibProblem &problem, const std::vector<double> &v);

  /**
   * The error measure of a global problem as Siconos 4.4 computes it
   * (gfc3d_compute_error): the relative force imbalance plus the relative
   * natural map of FCLIB's local merit function,
   *
   *   |f + H r - M v| / max(|f|, |M v|, |H r|)
   *   + sqrt(sum_c |r_c - P_K(r_c - (u_c + mu |u_t,c| e_n))|^2) / max(|u|, |r|)
   *
   * with u = H^T v + w recomputed from v (a scale below the machine epsilon
   * leaves its part absolute). libfclib's own fclib_merit_global() returns 0.
   */
  double
  fclib_error(const FclibProblem &problem, const FclibSolution &solution);

  /// |x - y| / |y| (|x - y| if y = 0), in the Euclidean norm.
  double
  relative_difference(const std::vector<double> &x, const std::vector<double> &y);
} // namespace FrictionalContact
