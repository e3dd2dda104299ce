#pragma once

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <suitesparse/SuiteSparse_config.h>

#include <vector>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * A square sparse matrix in compressed rows and its LU factorisation by
   * UMFPACK. The ordering and symbolic analysis are done once for the
   * pattern, the numeric factorisation for each set of values (deal.II's
   * SparseDirectUMFPACK redoes the analysis at every factorisation, and its
   * first use costs milliseconds of thread set-up). Owns the pattern, the
   * values and UMFPACK's factors.
   */
  class SparseLU
  {
  public:
    /// The pattern of @p pattern (column indices sorted in each row).
    explicit SparseLU(const DynamicSparsityPattern &pattern);

    ~SparseLU();

    SparseLU(const SparseLU &) = delete;
    SparseLU &
    operator=(const SparseLU &) = delete;

    /// The position of entry (i, j) in entries(); it must be in the pattern.
    std::size_t
    position(const unsigned int i, const unsigned int j) const;

    /// The number of entries of row @p i.
    std::size_t
    row_length(const unsigned int i) const
    {
      return row_start[i + 1] - row_start[i];
    }

    /// The values, in the order of the pattern's rows.
    std::vector<double> &
    entries()
    {
      return values;
    }

    /// Factorises the current values; false if the matrix is singular.
    bool
    factorize();

    /// The floating-point operations of the last factorisation and of one
    /// solve with it, as UMFPACK counts them.
    double factorization_flops = 0;
    double solve_flops         = 0;

    /// x = A^{-1} b with the last factorisation.
    void
    solve(Vector<double> &x, const Vector<double> &b) const;

    /// x = A^{-1} b for raw arrays of the matrix's size.
    void
    solve(double *x, const double *b) const;

  private:
    std::vector<SuiteSparse_long> row_start;
    std::vector<SuiteSparse_long> column;
    std::vector<double>           values;
    /// UMFPACK's settings and the work arrays of its solves.
    std::vector<double>           control;
    mutable std::vector<SuiteSparse_long> integer_workspace;
    mutable std::vector<double>           workspace;
    void                         *symbolic = nullptr;
    void                         *numeric  = nullptr;
  };
} // namespace FrictionalContact
