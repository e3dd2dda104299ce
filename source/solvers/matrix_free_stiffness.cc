#include <deal.II/fe/mapping_q1.h>

#include <frictional_contact/base/input.h>
#include <frictional_contact/solvers/matrix_free_stiffness.h>


namespace FrictionalContact
{
  template <int dim>
  MatrixFreeStiffness<dim>::MatrixFreeStiffness(const DoFHandler<dim>           &dof_handler,
                                                const AffineConstraints<double> &constraints,
                                                const LameParameters            &lame)
    : dof_handler(dof_handler)
    , owned_dofs(dof_handler.locally_owned_dofs())
  {
    typename MatrixFree<dim, double>::AdditionalData data;
    data.tasks_parallel_scheme = MatrixFree<dim, double>::AdditionalData::none;
    data.mapping_update_flags  = update_gradients | update_JxW_values;
    storage                    = std::make_shared<MatrixFree<dim, double>>();
    storage->reinit(MappingQ1<dim>(), dof_handler, constraints, QGauss<1>(2), data);
    K.initialize(storage);
    K.set_materials(lame);
    K.compute_diagonal();

    const LocalVector &diagonal = K.get_stiffness_diagonal();
    double             sum      = 0;
    for (const auto i : owned_dofs)
      if (constraints.is_constrained(i))
        constrained.push_back(owned_dofs.index_within_set(i));
      else
        sum += diagonal.local_element(owned_dofs.index_within_set(i));
    const MPI_Comm comm      = dof_handler.get_communicator();
    const double   n_free    = Utilities::MPI::sum(
      static_cast<double>(owned_dofs.n_elements() - constrained.size()), comm);
    const double   total     = Utilities::MPI::sum(sum, comm);
    constrained_diagonal     = n_free > 0 ? total / n_free : 1.;

    storage->initialize_dof_vector(src_copy);
    storage->initialize_dof_vector(dst_copy);
  }



  template <int dim>
  void
  MatrixFreeStiffness<dim>::vmult(Vector &dst, const Vector &src) const
  {
    copy_owned_entries(src, src_copy);
    K.vmult(dst_copy, src_copy);
    copy_owned_entries(dst_copy, dst);
    double       *values = dst.begin();
    const double *source = src.begin();
    for (const unsigned int i : constrained)
      values[i] = constrained_diagonal * source[i];
  }



  template <int dim>
  double
  MatrixFreeStiffness<dim>::diag_element(const types::global_dof_index i) const
  {
    const auto local = owned_dofs.index_within_set(i);
    return std::binary_search(constrained.begin(), constrained.end(), local) ?
             constrained_diagonal :
             K.get_stiffness_diagonal().local_element(local);
  }



  template <int dim>
  std::vector<FullMatrix<double>>
  MatrixFreeStiffness<dim>::blocks(
    const std::vector<std::vector<types::global_dof_index>> &nodes) const
  {
    // The wanted nodes are flagged (at their first dof) where the ranks
    // that own cells around them see it; each rank adds its cells' blocks
    // into column b of the nodal blocks (one vector per b), then the ranks
    // sum them.
    LocalVector flag;
    storage->initialize_dof_vector(flag);
    for (const auto &dofs : nodes)
      flag(dofs[0]) = 1;
    flag.update_ghost_values();
    std::vector<LocalVector> column(dim);
    for (LocalVector &c : column)
      storage->initialize_dof_vector(c);

    const MatrixFree<dim, double> &data       = *storage;
    constexpr unsigned int         n_vertices = GeometryInfo<dim>::vertices_per_cell;
    for (unsigned int batch = 0; batch < data.n_cell_batches(); ++batch)
      {
        const unsigned int filled = data.n_active_entries_per_cell_batch(batch);
        std::vector<std::vector<unsigned int>> wanted_vertices(filled);
        bool                                   any = false;
        for (unsigned int lane = 0; lane < filled; ++lane)
          {
            const auto cell = data.get_cell_iterator(batch, lane);
            for (unsigned int v = 0; v < n_vertices; ++v)
              if (flag(cell->vertex_dof_index(v, 0)) != 0)
                {
                  wanted_vertices[lane].push_back(v);
                  any = true;
                }
          }
        if (!any)
          continue;
        const std::vector<FullMatrix<double>> matrices = K.cell_matrices(batch);
        for (unsigned int lane = 0; lane < filled; ++lane)
          {
            const auto cell = data.get_cell_iterator(batch, lane);
            for (const unsigned int v : wanted_vertices[lane])
              for (unsigned int a = 0; a < dim; ++a)
                for (unsigned int b = 0; b < dim; ++b)
                  column[b](cell->vertex_dof_index(v, a)) +=
                    matrices[lane](a * n_vertices + v, b * n_vertices + v);
          }
      }
    for (LocalVector &c : column)
      c.compress(VectorOperation::add);

    std::vector<FullMatrix<double>> result;
    for (const auto &dofs : nodes)
      {
        FullMatrix<double> block(dim, dim);
        for (unsigned int a = 0; a < dim; ++a)
          {
            const bool a_held = std::binary_search(constrained.begin(),
                                                   constrained.end(),
                                                   owned_dofs.index_within_set(dofs[a]));
            for (unsigned int b = 0; b < dim; ++b)
              {
                // A constrained dof's row and column hold only the
                // diagonal, as in the assembled K.
                const bool b_held = std::binary_search(constrained.begin(),
                                                       constrained.end(),
                                                       owned_dofs.index_within_set(dofs[b]));
                block(a, b) = a_held || b_held ? 0. : column[b](dofs[a]);
              }
            if (a_held)
              block(a, a) = constrained_diagonal;
          }
        result.push_back(std::move(block));
      }
    return result;
  }



  template <int dim>
  const TrilinosWrappers::SparseMatrix &
  MatrixFreeStiffness<dim>::matrix(const std::string &purpose) const
  {
    throw InputError(purpose + " needs the assembled stiffness matrix, and "
                     "<Linear solver/Matrix-free stiffness> is true: set it to "
                     "false");
  }

  template class MatrixFreeStiffness<2>;
  template class MatrixFreeStiffness<3>;
} // namespace FrictionalContact
