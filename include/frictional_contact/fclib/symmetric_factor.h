#pragma once

#include <deal.II/lac/full_matrix.h>

#include <frictional_contact/fclib/fclib_problem.h>

#include <memory>
#include <vector>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * The Cholesky factorisation P^T L L^T P of a symmetric positive definite
   * sparse matrix (CHOLMOD, simplicial, with its fill-reducing ordering),
   * for eliminating the velocities of an FCLIB problem: B^T M^-1 B for the
   * m columns of B at once is Y^T Y with Y = L^-1 P B, forward solves with
   * all columns together and one BLAS product, instead of m forward and
   * backward solves with an LU factorisation. Owns CHOLMOD's workspace and
   * the factor.
   */
  class SymmetricFactor
  {
  public:
    SymmetricFactor();
    ~SymmetricFactor();
    SymmetricFactor(const SymmetricFactor &) = delete;
    SymmetricFactor &
    operator=(const SymmetricFactor &) = delete;

    /// Factorises the n x n matrix of @p entries (duplicates summed; the
    /// upper triangle is read, the matrix must be symmetric). False if it
    /// is not positive definite or CHOLMOD fails.
    bool
    factorize(const unsigned int n, const std::vector<MatrixEntry> &entries);

    /// The floating-point operations of an LU factorisation of the matrix
    /// (twice those of its Cholesky factorisation) and of one solve.
    double factorization_flops = 0;
    double solve_flops         = 0;

    /// x = M^-1 b, arrays of the matrix's size.
    void
    solve(double *x, const double *b) const;

    /// B^T M^-1 B for the dense n x m matrix @p B stored column by column.
    FullMatrix<double>
    congruence(const std::vector<double> &B, const unsigned int m) const;

  private:
    struct Workspace;
    std::unique_ptr<Workspace> workspace;
    unsigned int               size = 0;
  };
} // namespace FrictionalContact
