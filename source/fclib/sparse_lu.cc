#include <frictional_contact/fclib/sparse_lu.h>

#include <suitesparse/umfpack.h>

#include <algorithm>

namespace FrictionalContact
{
  SparseLU::SparseLU(const DynamicSparsityPattern &pattern)
    : row_start(pattern.n_rows() + 1, 0)
  {
    for (unsigned int i = 0; i < pattern.n_rows(); ++i)
      {
        for (auto entry = pattern.begin(i); entry != pattern.end(i); ++entry)
          column.push_back(entry->column());
        row_start[i + 1] = column.size();
      }
    values.assign(column.size(), 0.);
    integer_workspace.resize(pattern.n_rows());
    workspace.resize(5 * pattern.n_rows());
    // Solves without iterative refinement: a Newton step or an elimination
    // of M does not need the last digits, and each refinement step costs
    // another solve with the factors and a product with the matrix.
    control.resize(UMFPACK_CONTROL);
    umfpack_dl_defaults(control.data());
    control[UMFPACK_IRSTEP] = 0;
  }



  SparseLU::~SparseLU()
  {
    if (symbolic != nullptr)
      umfpack_dl_free_symbolic(&symbolic);
    if (numeric != nullptr)
      umfpack_dl_free_numeric(&numeric);
  }



  std::size_t
  SparseLU::position(const unsigned int i, const unsigned int j) const
  {
    const auto first = column.begin() + row_start[i];
    const auto last  = column.begin() + row_start[i + 1];
    return std::lower_bound(first, last, static_cast<SuiteSparse_long>(j)) -
           column.begin();
  }



  bool
  SparseLU::factorize()
  {
    // UMFPACK reads compressed columns: our rows are the columns of the
    // transpose, and solve() solves with the transpose of that.
    const SuiteSparse_long n = row_start.size() - 1;
    if (symbolic == nullptr &&
        umfpack_dl_symbolic(n, n, row_start.data(), column.data(),
                            values.data(), &symbolic, control.data(),
                            nullptr) != UMFPACK_OK)
      return false;
    if (numeric != nullptr)
      umfpack_dl_free_numeric(&numeric);
    double info[UMFPACK_INFO];
    const bool factorized =
      umfpack_dl_numeric(row_start.data(), column.data(), values.data(),
                         symbolic, &numeric, control.data(),
                         info) == UMFPACK_OK;
    if (factorized)
      {
        factorization_flops = info[UMFPACK_FLOPS];
        solve_flops         = 2 * (info[UMFPACK_LNZ] + info[UMFPACK_UNZ]);
      }
    return factorized;
  }



  void
  SparseLU::solve(double *x, const double *b) const
  {
    umfpack_dl_wsolve(UMFPACK_Aat, row_start.data(), column.data(),
                      values.data(), x, b, numeric, control.data(), nullptr,
                      integer_workspace.data(), workspace.data());
  }



  void
  SparseLU::solve(Vector<double> &x, const Vector<double> &b) const
  {
    solve(x.begin(), b.begin());
  }
} // namespace FrictionalContact
