#include <deal.II/lac/lapack_full_matrix.h>

#include <frictional_contact/fclib/symmetric_factor.h>

#include <suitesparse/cholmod.h>

#include <algorithm>
#include <cstring>

namespace FrictionalContact
{
  struct SymmetricFactor::Workspace
  {
    cholmod_common  common;
    cholmod_factor *factor = nullptr;

    Workspace()
    {
      cholmod_start(&common);
      // Simplicial, as L L^T: on example II's file of 675 unknowns the
      // whole Newton solve took 7.7 ms against 9.3 ms with the supernodal
      // factor (CHOLMOD's own choice there) and 10.4 ms with UMFPACK's LU
      // and m solves (medians of 15 runs); the problems that are condensed
      // are the small ones.
      common.supernodal = CHOLMOD_SIMPLICIAL;
      common.final_ll   = true;
    }

    ~Workspace()
    {
      cholmod_free_factor(&factor, &common);
      cholmod_finish(&common);
    }
  };



  namespace
  {
    /// A view of @p x (@p rows x @p columns, column by column) as CHOLMOD's
    /// dense matrix, without a copy.
    cholmod_dense
    dense_view(const double *x, const unsigned int rows, const unsigned int columns)
    {
      cholmod_dense view;
      std::memset(&view, 0, sizeof(view));
      view.nrow  = rows;
      view.ncol  = columns;
      view.nzmax = static_cast<std::size_t>(rows) * columns;
      view.d     = rows;
      view.x     = const_cast<double *>(x);
      view.xtype = CHOLMOD_REAL;
      view.dtype = CHOLMOD_DOUBLE;
      return view;
    }
  } // namespace



  SymmetricFactor::SymmetricFactor()
    : workspace(std::make_unique<Workspace>())
  {}



  SymmetricFactor::~SymmetricFactor() = default;



  bool
  SymmetricFactor::factorize(const unsigned int              n,
                             const std::vector<MatrixEntry> &entries)
  {
    cholmod_common &common = workspace->common;
    size                   = n;
    cholmod_triplet *triplet =
      cholmod_allocate_triplet(n, n, entries.size(), 1, CHOLMOD_REAL, &common);
    if (triplet == nullptr)
      return false;
    int    *rows    = static_cast<int *>(triplet->i);
    int    *columns = static_cast<int *>(triplet->j);
    double *values  = static_cast<double *>(triplet->x);
    std::size_t k   = 0;
    for (const MatrixEntry &e : entries)
      if (e.row <= e.column)
        {
          rows[k]    = e.row;
          columns[k] = e.column;
          values[k]  = e.value;
          ++k;
        }
    triplet->nnz           = k;
    cholmod_sparse *matrix = cholmod_triplet_to_sparse(triplet, k, &common);
    cholmod_free_triplet(&triplet, &common);
    if (matrix == nullptr)
      return false;
    cholmod_free_factor(&workspace->factor, &common);
    workspace->factor = cholmod_analyze(matrix, &common);
    const bool factorized =
      workspace->factor != nullptr &&
      cholmod_factorize(matrix, workspace->factor, &common) &&
      common.status == CHOLMOD_OK && workspace->factor->minor == n;
    cholmod_free_sparse(&matrix, &common);
    // In LU's terms, as SparseLU counts them: the unit of the cost rules
    // that compare a factorisation of M with one of a coupled system.
    factorization_flops = 2 * common.fl;
    solve_flops         = 4 * common.lnz;
    return factorized;
  }



  void
  SymmetricFactor::solve(double *x, const double *b) const
  {
    cholmod_common &common = workspace->common;
    cholmod_dense   rhs    = dense_view(b, size, 1);
    cholmod_dense *solution =
      cholmod_solve(CHOLMOD_A, workspace->factor, &rhs, &common);
    const double *values = static_cast<const double *>(solution->x);
    std::copy(values, values + size, x);
    cholmod_free_dense(&solution, &common);
  }



  FullMatrix<double>
  SymmetricFactor::congruence(const std::vector<double> &B, const unsigned int m) const
  {
    cholmod_common &common  = workspace->common;
    cholmod_dense   columns = dense_view(B.data(), size, m);
    cholmod_dense  *permuted =
      cholmod_solve(CHOLMOD_P, workspace->factor, &columns, &common);
    cholmod_dense *Y = cholmod_solve(CHOLMOD_L, workspace->factor, permuted, &common);
    cholmod_free_dense(&permuted, &common);
    // Y^T Y with BLAS (syrk: Tmmult of a matrix with itself).
    LAPACKFullMatrix<double> Y_full(size, m), product(m, m);
    const double            *y = static_cast<const double *>(Y->x);
    for (unsigned int j = 0; j < m; ++j)
      for (unsigned int i = 0; i < size; ++i)
        Y_full(i, j) = y[static_cast<std::size_t>(j) * size + i];
    cholmod_free_dense(&Y, &common);
    Y_full.Tmmult(product, Y_full);
    FullMatrix<double> result(m, m);
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = 0; j < m; ++j)
        result(i, j) = product(i, j);
    return result;
  }
} // namespace FrictionalContact
