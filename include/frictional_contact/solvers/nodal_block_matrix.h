#pragma once

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <vector>

class Epetra_Vector;

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * The product with a Trilinos matrix of a vector-valued field, stored as
   * dense n x n blocks, one per pair of coupled nodes (n components per
   * node): one column index per block instead of one per entry, which
   * makes the product faster than Epetra's (doc/performance.md). The
   * values are kept in single precision: the copy serves preconditioners,
   * which need a fixed operator close to the matrix, not the matrix
   * itself. Usable when the rows of every rank are nodes of n consecutive
   * indices (deal.II's numbering of an FESystem); otherwise empty().
   * Owns the blocks and the vector the product gathers ghost values into;
   * the matrix must outlive it.
   */
  class NodalBlockMatrix
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;
    using Number = float;

    /// Copies @p matrix in blocks of @p n_components, if every rank can.
    /// Collective.
    NodalBlockMatrix(const TrilinosWrappers::SparseMatrix &matrix,
                     const unsigned int                    n_components);
    ~NodalBlockMatrix();

    /// Whether the matrix could not be stored in nodal blocks.
    bool
    empty() const
    {
      return block_size == 0;
    }

    /// dst = matrix src (with the single-precision values). Collective.
    void
    vmult(Vector &dst, const Vector &src) const;

  private:
    /// Whether the rows of @p matrix on this rank come in groups of @p n,
    /// one node each, and are the first columns.
    static bool
    rows_grouped_by_node(const TrilinosWrappers::SparseMatrix &matrix,
                         const unsigned int                    n);

    /// Numbers the nodes of the columns (column_position).
    void
    number_column_nodes();

    /// Calls f(row component, position in the vector by nodes, value) for
    /// every entry of the rows of block row @p node.
    template <typename EntryFunction>
    void
    for_each_entry(const int node, EntryFunction &&f) const;

    /// Appends the nodes block row @p node couples to (zero blocks where
    /// some of its rows have no entry) and its offset.
    void
    couple_block_row(const int node);

    /// Copies the entries of block row @p node into its blocks.
    void
    copy_block_row(const int node);

    const TrilinosWrappers::SparseMatrix &matrix;
    unsigned int                          block_size = 0;
    /// Block row i has the blocks offsets[i] to offsets[i + 1] - 1, each
    /// with the node of its columns (numbered as in column_position) and
    /// its values (row-major).
    std::vector<int>                       offsets, block_columns;
    std::vector<Number>                    values;
    /// Column l of the matrix is entry column_position[l] of the vector
    /// by nodes (n per node) that the blocks multiply; columns_in_place if
    /// that is l itself.
    std::vector<int>                       column_position;
    bool                                   columns_in_place = true;
    mutable std::vector<double>            by_node;
    mutable std::unique_ptr<Epetra_Vector> ghosted_src;
  };
} // namespace FrictionalContact
