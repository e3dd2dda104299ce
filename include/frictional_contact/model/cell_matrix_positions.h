#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <Epetra_Map.h>

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * Where the entries of each cell's matrix live in the value array of an
   * assembled Trilinos matrix, so that a tangent assembled anew at every
   * Newton step (finite strain) adds its cell matrices there directly,
   * without Epetra's lookups of global rows and columns (a binary search
   * per entry: more than the element kernel in a profile of Hertz 3D),
   * and its cell forces into a vector of the same rows by their local
   * indices (through AffineConstraints, each entry's lookups took a tenth
   * of a 2D cell's force and tangent, by callgrind).
   * Only for the locally owned cells whose dofs are all rows of this rank
   * and none constrained; the others go through AffineConstraints as
   * before. A Q1 vertex's dim dofs are neighbours in every row that holds
   * one, so a position is kept per (row, vertex): dim 4^dim positions
   * per cell (192 in 3D), the local index of each of the cell's rows,
   * and a hash of the cell's dofs. Owns those and the fingerprint of the
   * mesh, constraints and matrix they were taken for (with the matrix's
   * rows); taken again when it changes.
   */
  template <int dim>
  class CellMatrixPositions
  {
  public:
    /// Takes the positions again unless @p matrix, @p dof_handler and
    /// @p constraints are those they were taken for. Not collective.
    void
    update(const DoFHandler<dim>           &dof_handler,
           const AffineConstraints<double> &constraints,
           TrilinosWrappers::SparseMatrix  &matrix);

    /// Whether the cell of @p active_cell_index, with the dofs
    /// @p dof_indices, has positions (the dofs checked by a hash, so that
    /// positions never serve a cell they were not taken for).
    bool
    has(const unsigned int                          active_cell_index,
        const std::vector<types::global_dof_index> &dof_indices) const
    {
      return active_cell_index < first.size() && first[active_cell_index] != none &&
             dof_hashes[active_cell_index] == hash(dof_indices);
    }

    /**
     * Adds @p cell_matrix (in the order of the cell's dof indices) to the
     * matrix the positions were taken for. Only where has().
     */
    void
    add(const unsigned int active_cell_index, const FullMatrix<double> &cell_matrix) const;

    /// The local values of @p vector if its rows are those of the matrix
    /// (same Epetra map), for add_to_vector(); else nullptr.
    double *
    local_values(TrilinosWrappers::MPI::Vector &vector) const;

    /// Adds @p cell_vector (in the order of the cell's dof indices) to the
    /// @p values that local_values() gave. Only where has().
    void
    add_to_vector(const unsigned int            active_cell_index,
                  const dealii::Vector<double> &cell_vector,
                  double                       *values) const;

  private:
    /// FNV-1a of the dof indices.
    static std::uint64_t
    hash(const std::vector<types::global_dof_index> &dof_indices)
    {
      std::uint64_t h = 14695981039346656037ull;
      for (const types::global_dof_index i : dof_indices)
        h = (h ^ static_cast<std::uint64_t>(i)) * 1099511628211ull;
      return h;
    }

    static constexpr unsigned int dofs_per_cell = dim * (1u << dim);
    static constexpr unsigned int none          = static_cast<unsigned int>(-1);

    /// What the positions were taken for: the value array (where add()
    /// adds), size and rows of the matrix, the mesh and dofs, and the
    /// constrained dofs.
    struct Fingerprint
    {
      double                 *values            = nullptr;
      int                     n_entries         = -1;
      unsigned int            n_active_cells    = 0;
      types::global_dof_index n_dofs            = 0;
      types::global_dof_index n_constraints     = 0;
      types::global_dof_index constrained_sum   = 0;
      /// The rows of this rank: their number and first and last.
      std::array<long long, 3> rows = {{-1, -1, -1}};

      bool
      operator==(const Fingerprint &other) const
      {
        return values == other.values && n_entries == other.n_entries && rows == other.rows &&
               n_active_cells == other.n_active_cells && n_dofs == other.n_dofs &&
               n_constraints == other.n_constraints &&
               constrained_sum == other.constrained_sum;
      }
    };

    Fingerprint fingerprint;
    /// The matrix's rows (a copy: Epetra maps share their data).
    std::unique_ptr<Epetra_Map> matrix_rows;
    /// Per active cell, the first of its positions, or none, and the
    /// hash of its dofs.
    std::vector<unsigned int>  first;
    std::vector<std::uint64_t> dof_hashes;
    /// Per cell with positions, for each local row i and vertex b, the
    /// position of the column of b's first dof in row i; and the local
    /// index of each row (from first / n_vertices).
    std::vector<int> positions;
    std::vector<int> local_rows;
  };
} // namespace FrictionalContact
