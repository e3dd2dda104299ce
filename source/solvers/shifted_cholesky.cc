#include <frictional_contact/base/input.h>
#include <frictional_contact/solvers/shifted_cholesky.h>

#include <suitesparse/cholmod.h>

#include <Epetra_CrsMatrix.h>

#include <algorithm>
#include <cstring>

namespace FrictionalContact
{
  /// CHOLMOD's state: its common block, the lower triangle of K, the
  /// factor and the solve's work vectors, kept between solves.
  struct ShiftedCholesky::Workspace
  {
    cholmod_common  common;
    cholmod_sparse *matrix   = nullptr;
    cholmod_factor *factor   = nullptr;
    cholmod_dense  *solution = nullptr;
    cholmod_dense  *work_y   = nullptr;
    cholmod_dense  *work_e   = nullptr;

    Workspace()
    {
      cholmod_start(&common);
      // Quiet: failures are reported through the status and our errors.
      common.print = 0;
    }

    ~Workspace()
    {
      cholmod_free_dense(&solution, &common);
      cholmod_free_dense(&work_y, &common);
      cholmod_free_dense(&work_e, &common);
      cholmod_free_factor(&factor, &common);
      cholmod_free_sparse(&matrix, &common);
      cholmod_finish(&common);
    }
  };



  namespace
  {
    [[noreturn]] void
    fail(const std::string &what, const int status)
    {
      std::string cause;
      if (status == CHOLMOD_OUT_OF_MEMORY)
        cause = " (out of memory): set <Linear solver/Preconditioner> = "
                "jacobi or amg";
      else if (status == CHOLMOD_NOT_POSDEF)
        cause = " (the matrix is not positive definite: is every body "
                "held against rigid motion?)";
      throw SolverError("the sparse Cholesky factorization (CHOLMOD) " + what +
                        " failed with status " + std::to_string(status) +
                        cause);
    }
  } // namespace



  ShiftedCholesky::ShiftedCholesky() = default;

  ShiftedCholesky::~ShiftedCholesky() = default;



  bool
  ShiftedCholesky::applicable(const TrilinosWrappers::SparseMatrix &K)
  {
    return Utilities::MPI::n_mpi_processes(K.get_mpi_communicator()) == 1;
  }



  void
  ShiftedCholesky::clear()
  {
    workspace.reset();
    factor_shift = -1;
  }



  void
  ShiftedCholesky::analyze(const TrilinosWrappers::SparseMatrix &K)
  {
    clear();
    workspace = std::make_unique<Workspace>();
    cholmod_common &common = workspace->common;

    // K's rows are its columns (K is symmetric): the entries right of the
    // diagonal of row i are the lower triangle of column i.
    const Epetra_CrsMatrix &crs = K.trilinos_matrix();
    const int               n   = crs.NumMyRows();
    std::size_t             lower_entries = 0;
    for (int row = 0; row < n; ++row)
      {
        int     length;
        double *values;
        int    *columns;
        crs.ExtractMyRowView(row, length, values, columns);
        for (int e = 0; e < length; ++e)
          lower_entries += crs.GCID(columns[e]) >= crs.GRID(row);
      }
    workspace->matrix = cholmod_allocate_sparse(
      n, n, lower_entries, /*sorted*/ 0, /*packed*/ 1, /*stype*/ -1,
      CHOLMOD_REAL, &common);
    if (workspace->matrix == nullptr)
      fail("of K's copy", common.status);
    int    *column_start = static_cast<int *>(workspace->matrix->p);
    int    *row_index    = static_cast<int *>(workspace->matrix->i);
    double *value        = static_cast<double *>(workspace->matrix->x);
    std::size_t position = 0;
    for (int row = 0; row < n; ++row)
      {
        column_start[row] = position;
        int     length;
        double *values;
        int    *columns;
        crs.ExtractMyRowView(row, length, values, columns);
        for (int e = 0; e < length; ++e)
          if (crs.GCID(columns[e]) >= crs.GRID(row))
            {
              row_index[position] = crs.GCID(columns[e]);
              value[position]     = values[e];
              ++position;
            }
      }
    column_start[n] = position;

    workspace->factor = cholmod_analyze(workspace->matrix, &common);
    if (workspace->factor == nullptr)
      fail("ordering", common.status);
  }



  void
  ShiftedCholesky::factorize(const double sigma)
  {
    cholmod_common &common = workspace->common;
    double          beta[2] = {sigma, 0.};
    if (!cholmod_factorize_p(workspace->matrix, beta, nullptr, 0,
                             workspace->factor, &common) ||
        common.status != CHOLMOD_OK)
      fail("of K + " + Input::to_text(sigma) + " I", common.status);
    factor_shift = sigma;
  }



  void
  ShiftedCholesky::vmult(TrilinosWrappers::MPI::Vector       &dst,
                         const TrilinosWrappers::MPI::Vector &src) const
  {
    cholmod_common &common = workspace->common;
    // A view of src as CHOLMOD's right-hand side, without a copy.
    cholmod_dense right_hand_side;
    std::memset(&right_hand_side, 0, sizeof(right_hand_side));
    right_hand_side.nrow  = src.locally_owned_size();
    right_hand_side.ncol  = 1;
    right_hand_side.nzmax = src.locally_owned_size();
    right_hand_side.d     = src.locally_owned_size();
    right_hand_side.x     = const_cast<double *>(src.begin());
    right_hand_side.xtype = CHOLMOD_REAL;
    right_hand_side.dtype = CHOLMOD_DOUBLE;
    if (!cholmod_solve2(CHOLMOD_A, workspace->factor, &right_hand_side,
                        nullptr, &workspace->solution, nullptr,
                        &workspace->work_y, &workspace->work_e, &common))
      fail("solve", common.status);
    const double *x = static_cast<const double *>(workspace->solution->x);
    std::copy(x, x + dst.locally_owned_size(), dst.begin());
  }



  double
  ShiftedCholesky::predicted_factor_nonzeros() const
  {
    return workspace != nullptr ? workspace->common.lnz : 0.;
  }
} // namespace FrictionalContact
