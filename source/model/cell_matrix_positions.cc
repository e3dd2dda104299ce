#include <frictional_contact/model/cell_matrix_positions.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_FEVector.h>

#include <algorithm>

namespace FrictionalContact
{
  template <int dim>
  void
  CellMatrixPositions<dim>::update(const DoFHandler<dim>           &dof_handler,
                                   const AffineConstraints<double> &constraints,
                                   TrilinosWrappers::SparseMatrix  &matrix)
  {
    // deal.II 9.4 gives its Epetra matrix as const only; @p matrix is not.
    Epetra_CrsMatrix &crs = const_cast<Epetra_CrsMatrix &>(matrix.trilinos_matrix());
    Fingerprint now;
    int        *row_starts = nullptr, *columns = nullptr;
    double     *entries    = nullptr;
    // Only a matrix whose values are one array (storage optimized).
    if (crs.Filled() && crs.ExtractCrsDataPointers(row_starts, columns, entries) == 0)
      {
        now.values    = entries;
        now.n_entries = crs.NumMyNonzeros();
        now.rows      = {{crs.RowMap().NumMyElements(), crs.RowMap().MinMyGID64(),
                          crs.RowMap().MaxMyGID64()}};
      }
    now.n_active_cells = dof_handler.get_triangulation().n_active_cells();
    now.n_dofs         = dof_handler.n_dofs();
    now.n_constraints  = constraints.n_constraints();
    for (const auto &line : constraints.get_lines())
      now.constrained_sum += line.index;
    if (now == fingerprint)
      return;
    fingerprint = now;
    matrix_rows = std::make_unique<Epetra_Map>(crs.RowMap());
    first.assign(now.n_active_cells, none);
    dof_hashes.assign(now.n_active_cells, 0);
    positions.clear();
    local_rows.clear();
    if (fingerprint.values == nullptr)
      return;

    constexpr unsigned int n_vertices = GeometryInfo<dim>::vertices_per_cell;
    const Epetra_Map      &row_map    = crs.RowMap();
    const Epetra_Map      &column_map = crs.ColMap();
    // add() takes the dofs of a cell vertex by vertex, a vertex's
    // components in a row (dof i = dim b + c), as FESystem numbers those
    // of a Q1 element.
    const auto &fe = dof_handler.get_fe();
    if (fe.n_dofs_per_cell() != dofs_per_cell)
      return;
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      if (fe.system_to_component_index(i) != std::make_pair(i % dim, i / dim))
        return;
    std::vector<types::global_dof_index> dof_indices(dofs_per_cell);
    std::array<int, dofs_per_cell>       rows, cols;
    std::vector<int>                     cell_positions(dofs_per_cell * n_vertices);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        cell->get_dof_indices(dof_indices);
        bool usable = true;
        for (unsigned int i = 0; i < dofs_per_cell && usable; ++i)
          {
            rows[i] = row_map.LID(static_cast<TrilinosWrappers::types::int_type>(dof_indices[i]));
            cols[i] = column_map.LID(static_cast<TrilinosWrappers::types::int_type>(dof_indices[i]));
            usable  = rows[i] >= 0 && cols[i] >= 0 && !constraints.is_constrained(dof_indices[i]);
          }
        // Vertex b's columns, which must be neighbours in every row.
        std::array<std::array<int, dim>, n_vertices> vertex_columns;
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          vertex_columns[i / dim][i % dim] = cols[i];
        for (unsigned int i = 0; i < dofs_per_cell && usable; ++i)
          {
            const int *begin = columns + row_starts[rows[i]];
            const int *end   = columns + row_starts[rows[i] + 1];
            for (unsigned int b = 0; b < n_vertices && usable; ++b)
              {
                // Epetra keeps a row's columns sorted by local index.
                const int *at = std::lower_bound(begin, end, vertex_columns[b][0]);
                usable        = at != end && *at == vertex_columns[b][0] &&
                         at + dim <= end;
                for (unsigned int c = 1; c < dim && usable; ++c)
                  usable = at[c] == vertex_columns[b][c];
                if (usable)
                  cell_positions[i * n_vertices + b] = static_cast<int>(at - columns);
              }
          }
        if (!usable)
          continue;
        first[cell->active_cell_index()]      = positions.size();
        dof_hashes[cell->active_cell_index()] = hash(dof_indices);
        positions.insert(positions.end(), cell_positions.begin(), cell_positions.end());
        local_rows.insert(local_rows.end(), rows.begin(), rows.end());
      }
  }



  template <int dim>
  void
  CellMatrixPositions<dim>::add(const unsigned int        active_cell_index,
                                const FullMatrix<double> &cell_matrix) const
  {
    constexpr unsigned int n_vertices = GeometryInfo<dim>::vertices_per_cell;
    const int             *position   = positions.data() + first[active_cell_index];
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      for (unsigned int b = 0; b < n_vertices; ++b)
        {
          double *value = fingerprint.values + position[i * n_vertices + b];
          for (unsigned int c = 0; c < dim; ++c)
            value[c] += cell_matrix(i, dim * b + c);
        }
  }



  template <int dim>
  double *
  CellMatrixPositions<dim>::local_values(TrilinosWrappers::MPI::Vector &vector) const
  {
    if (fingerprint.values == nullptr || !matrix_rows)
      return nullptr;
    Epetra_FEVector &values = vector.trilinos_vector();
    if (!values.Map().SameAs(*matrix_rows))
      return nullptr;
    return values[0];
  }



  template <int dim>
  void
  CellMatrixPositions<dim>::add_to_vector(const unsigned int            active_cell_index,
                                          const dealii::Vector<double> &cell_vector,
                                          double                       *values) const
  {
    constexpr unsigned int n_vertices = GeometryInfo<dim>::vertices_per_cell;
    const int             *row        = local_rows.data() + first[active_cell_index] / n_vertices;
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      values[row[i]] += cell_vector(i);
  }

  template class CellMatrixPositions<2>;
  template class CellMatrixPositions<3>;
} // namespace FrictionalContact
