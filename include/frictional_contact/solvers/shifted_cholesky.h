#pragma once

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * A sparse Cholesky factorization L L^T = K + sigma_ref I of a symmetric
   * positive definite stiffness K held by one process (CHOLMOD, SuiteSparse,
   * with its fill-reducing ordering). Owns the CHOLMOD copy of K, its
   * symbolic analysis (done once) and the numeric factor at the last shift
   * factorize() was given; vmult() applies (K + sigma_ref I)^-1, the
   * preconditioner of CG for K + sigma I with sigma near sigma_ref.
   */
  class ShiftedCholesky
  {
  public:
    ShiftedCholesky();
    ~ShiftedCholesky();
    ShiftedCholesky(const ShiftedCholesky &) = delete;
    ShiftedCholesky &
    operator=(const ShiftedCholesky &) = delete;

    /// Whether a factorization of @p K can be made: K lives on one process.
    static bool
    applicable(const TrilinosWrappers::SparseMatrix &K);

    /// Copies K (its lower triangle) and orders its factor; drops the
    /// numeric factor. Throws a SolverError if CHOLMOD fails.
    void
    analyze(const TrilinosWrappers::SparseMatrix &K);

    /// Factors K + sigma I; throws a SolverError if that is not positive
    /// definite or does not fit in memory.
    void
    factorize(const double sigma);

    /// dst = (K + sigma_ref I)^-1 src.
    void
    vmult(TrilinosWrappers::MPI::Vector       &dst,
          const TrilinosWrappers::MPI::Vector &src) const;

    /// The shift of the numeric factor (-1 before the first factorize()).
    double
    shift() const
    {
      return factor_shift;
    }

    /// Drops K's copy and the factors.
    void
    clear();

    /// Whether analyze() was called since the last clear().
    bool
    analyzed() const
    {
      return workspace != nullptr;
    }

    /// The nonzeros of the factor L that analyze() predicts.
    double
    predicted_factor_nonzeros() const;

  private:
    struct Workspace;
    std::unique_ptr<Workspace> workspace;
    double                     factor_shift = -1;
  };
} // namespace FrictionalContact
