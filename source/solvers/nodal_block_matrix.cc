#include <deal.II/base/mpi.h>

#include <frictional_contact/solvers/nodal_block_matrix.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Import.h>
#include <Epetra_Vector.h>

#include <algorithm>
#include <unordered_map>

namespace FrictionalContact
{
  namespace
  {
    /// y = A x for the blocks of n x n (n known at compile time).
    template <int n, typename Number>
    void
    block_product(const std::vector<int>    &offsets,
                  const std::vector<int>    &block_columns,
                  const std::vector<Number> &values,
                  const double              *x,
                  double                    *y)
    {
      const int     n_block_rows = static_cast<int>(offsets.size()) - 1;
      const Number *v            = values.data();
      for (int node = 0; node < n_block_rows; ++node)
        {
          double sum[n] = {};
          for (int k = offsets[node]; k < offsets[node + 1]; ++k, v += n * n)
            {
              const double *x_k = x + n * block_columns[k];
              for (int a = 0; a < n; ++a)
                for (int b = 0; b < n; ++b)
                  sum[a] += v[a * n + b] * x_k[b];
            }
          for (int a = 0; a < n; ++a)
            y[n * node + a] = sum[a];
        }
    }
  } // namespace



  NodalBlockMatrix::NodalBlockMatrix(
    const TrilinosWrappers::SparseMatrix &matrix,
    const unsigned int                    n_components)
    : matrix(matrix)
  {
    const bool usable = (n_components == 2 || n_components == 3) &&
                        rows_grouped_by_node(matrix, n_components);
    if (Utilities::MPI::logical_or(!usable, matrix.get_mpi_communicator()))
      return;
    block_size                = n_components;
    const Epetra_CrsMatrix &A = matrix.trilinos_matrix();
    number_column_nodes();
    const int n_block_rows = A.NumMyRows() / n_components;
    // The coupled nodes first, then the values, each allocated once.
    block_columns.reserve(A.NumMyNonzeros() / n_components);
    offsets.assign(1, 0);
    for (int node = 0; node < n_block_rows; ++node)
      couple_block_row(node);
    block_columns.shrink_to_fit();
    values.assign(block_columns.size() * n_components * n_components, 0);
    for (int node = 0; node < n_block_rows; ++node)
      copy_block_row(node);
    ghosted_src = std::make_unique<Epetra_Vector>(A.ColMap());
  }



  NodalBlockMatrix::~NodalBlockMatrix() = default;



  bool
  NodalBlockMatrix::rows_grouped_by_node(
    const TrilinosWrappers::SparseMatrix &matrix,
    const unsigned int                    n)
  {
    const Epetra_CrsMatrix &A = matrix.trilinos_matrix();
    const int               b = n;
    if (A.Exporter() != nullptr || A.NumMyRows() % b != 0)
      return false;
    // Row l is component l % n of the node whose first row is l - l % n,
    // and the columns begin with the rows, in the same order.
    for (int l = 0; l < A.NumMyRows(); ++l)
      if (A.RowMap().GID(l - l % b) % b != 0 ||
          A.RowMap().GID(l) != A.RowMap().GID(l - l % b) + l % b ||
          A.ColMap().GID(l) != A.RowMap().GID(l))
        return false;
    return true;
  }



  void
  NodalBlockMatrix::number_column_nodes()
  {
    // The nodes of the rows keep their numbers; a ghost node gets the
    // next number when one of its components first appears among the
    // columns (not all of them need to: a constrained one may not).
    const Epetra_Map &columns = matrix.trilinos_matrix().ColMap();
    const int         n       = block_size;
    const int         n_rows  = matrix.trilinos_matrix().NumMyRows();
    std::unordered_map<long long, int> ghost_nodes;
    column_position.resize(columns.NumMyElements());
    columns_in_place = true;
    for (int l = 0; l < columns.NumMyElements(); ++l)
      {
        const long long global = columns.GID64(l);
        int             node   = l / n;
        if (l >= n_rows)
          node = ghost_nodes
                   .emplace(global / n,
                            n_rows / n + static_cast<int>(ghost_nodes.size()))
                   .first->second;
        column_position[l] = n * node + static_cast<int>(global % n);
        columns_in_place   = columns_in_place && column_position[l] == l;
      }
    if (!columns_in_place)
      by_node.assign(n * (n_rows / n + static_cast<int>(ghost_nodes.size())), 0.);
  }



  template <typename EntryFunction>
  void
  NodalBlockMatrix::for_each_entry(const int node, EntryFunction &&f) const
  {
    const Epetra_CrsMatrix &A = matrix.trilinos_matrix();
    const int               n = block_size;
    for (int a = 0; a < n; ++a)
      {
        int     length;
        double *row_values;
        int    *indices;
        A.ExtractMyRowView(node * n + a, length, row_values, indices);
        for (int k = 0; k < length; ++k)
          f(a, column_position[indices[k]], row_values[k]);
      }
  }



  void
  NodalBlockMatrix::couple_block_row(const int node)
  {
    const int         n     = block_size;
    const std::size_t first = block_columns.size();
    for_each_entry(node, [&](int, const int position, double) {
      block_columns.push_back(position / n);
    });
    std::sort(block_columns.begin() + first, block_columns.end());
    block_columns.erase(std::unique(block_columns.begin() + first,
                                    block_columns.end()),
                        block_columns.end());
    offsets.push_back(block_columns.size());
  }



  void
  NodalBlockMatrix::copy_block_row(const int node)
  {
    const int  n     = block_size;
    const auto first = block_columns.begin() + offsets[node];
    const auto last  = block_columns.begin() + offsets[node + 1];
    for_each_entry(node, [&](const int a, const int position, const double value) {
      const std::size_t block =
        std::lower_bound(first, last, position / n) - block_columns.begin();
      values[block * n * n + a * n + position % n] = value;
    });
  }



  void
  NodalBlockMatrix::vmult(Vector &dst, const Vector &src) const
  {
    Assert(!empty(), ExcInternalError());
    const Epetra_CrsMatrix &A = matrix.trilinos_matrix();
    const double           *x = src.begin();
    if (const Epetra_Import *importer = A.Importer())
      {
        const Epetra_Vector owned(View, A.RowMap(), const_cast<double *>(x));
        ghosted_src->Import(owned, *importer, Insert);
        x = ghosted_src->Values();
      }
    if (!columns_in_place)
      {
        // Missing components of ghost nodes stay zero in by_node.
        for (std::size_t l = 0; l < column_position.size(); ++l)
          by_node[column_position[l]] = x[l];
        x = by_node.data();
      }
    if (block_size == 3)
      block_product<3>(offsets, block_columns, values, x, dst.begin());
    else
      block_product<2>(offsets, block_columns, values, x, dst.begin());
  }
} // namespace FrictionalContact
