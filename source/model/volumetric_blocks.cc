#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <frictional_contact/model/volumetric_blocks.h>

namespace FrictionalContact
{
  namespace
  {
    /// The bulk modulus (of dim dimensions) of the reduced stiffness A:
    /// that of the same shear modulus at nu = 0.4 (lambda = 4 G). Chosen by
    /// measurement (doc/performance.md): GMRES on the mixed system of
    /// Lame's sphere at nu = 0.4999 took 105 iterations with nu = 0.3,
    /// 81 with 0.4, 79 with 0.45 and 135 with 0.48.
    template <int dim>
    double
    reduced_bulk_modulus(const ElasticConstants<dim> &material)
    {
      return 4. * material.shear_modulus + 2. * material.shear_modulus / dim;
    }



    /// kappa - kappa_0: the part of the bulk modulus the split takes out
    /// (0: none, the material is not B-bar or not stiff enough).
    template <int dim>
    double
    penalty_modulus(const ElasticConstants<dim> &material)
    {
      return material.mean_dilatation ?
               std::max(0., material.bulk_modulus - reduced_bulk_modulus(material)) :
               0.;
    }



    /// 1 / kappa_p + 1 / M_0, per volume, of the approximate Schur complement.
    template <int dim>
    double
    schur_compliance(const ElasticConstants<dim> &material)
    {
      return 1. / penalty_modulus(material) +
             1. / (reduced_bulk_modulus(material) +
                   2. * material.shear_modulus * (dim - 1.) / dim);
    }
  } // namespace



  template <int dim>
  VolumetricBlocks<dim>::VolumetricBlocks(const Materials<dim> &materials)
    : materials(materials)
    , cell_fe(0)
  {}



  template <int dim>
  void
  VolumetricBlocks<dim>::setup(const DoFHandler<dim>           &dof_handler,
                               const AffineConstraints<double> &constraints,
                               const TrilinosWrappers::SparseMatrix &stiffness)
  {
    any_penalty = false;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        any_penalty =
          any_penalty || penalty_modulus(materials.of(cell->material_id()).elastic()) > 0;
    any_penalty = Utilities::MPI::logical_or(any_penalty,
                                             stiffness.get_mpi_communicator());
    // The split is written for the dim-dimensional bulk modulus: an
    // axisymmetric body's volumetric strain has the hoop part too.
    any_penalty = any_penalty && !materials.axisymmetric();
    if (!active())
      return;
    const MPI_Comm comm = stiffness.get_mpi_communicator();
    no_constraints.close();
    cell_numbering.reinit(dof_handler.get_triangulation());
    cell_numbering.distribute_dofs(cell_fe);
    const IndexSet &owned_cells = cell_numbering.locally_owned_dofs();
    const IndexSet &owned_dofs  = dof_handler.locally_owned_dofs();

    reduced_stiffness.reinit(stiffness);
    TrilinosWrappers::SparsityPattern pattern(owned_cells,
                                              owned_dofs,
                                              owned_cells,
                                              comm);
    std::vector<types::global_dof_index> dofs(dof_handler.get_fe().n_dofs_per_cell());
    std::vector<types::global_dof_index> row(1);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          typename DoFHandler<dim>::active_cell_iterator numbered(
            &cell->get_triangulation(), cell->level(), cell->index(), &cell_numbering);
          numbered->get_dof_indices(row);
          no_constraints.add_entries_local_to_global(row, constraints, dofs, pattern, false);
        }
    pattern.compress();
    divergence.reinit(pattern);
    compliance.reinit(owned_cells, comm);
    inverse_schur.reinit(owned_cells, comm);
    row_weight.reinit(owned_cells, comm);
    cell_matrix.reinit(dofs.size(), dofs.size());
    cell_row.reinit(1, dofs.size());
  }



  template <int dim>
  void
  VolumetricBlocks<dim>::start_assembly()
  {
    if (!active())
      return;
    reduced_stiffness = 0;
    divergence        = 0;
    compliance        = 0;
    inverse_schur     = 0;
    row_weight        = 0;
  }



  template <int dim>
  void
  VolumetricBlocks<dim>::add_cell(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const FullMatrix<double>                             &cell_stiffness,
    const std::vector<double>                            &divergence_integral,
    const double                                          volume,
    const std::vector<types::global_dof_index>           &dof_indices,
    const AffineConstraints<double>                      &constraints)
  {
    const ElasticConstants<dim> &material = materials.of(cell->material_id()).elastic();
    const double       penalty = penalty_modulus(material);
    const unsigned int n       = dof_indices.size();
    for (unsigned int i = 0; i < n; ++i)
      {
        for (unsigned int j = 0; j < n; ++j)
          cell_matrix(i, j) = cell_stiffness(i, j) - penalty *
                                                       divergence_integral[i] *
                                                       divergence_integral[j] /
                                                       volume;
        cell_row(0, i) = penalty > 0 ? divergence_integral[i] : 0.;
      }
    constraints.distribute_local_to_global(cell_matrix, dof_indices, reduced_stiffness);

    typename DoFHandler<dim>::active_cell_iterator numbered(
      &cell->get_triangulation(), cell->level(), cell->index(), &cell_numbering);
    std::vector<types::global_dof_index> row(1);
    numbered->get_dof_indices(row);
    no_constraints.distribute_local_to_global(
      cell_row, row, constraints, dof_indices, divergence);
    if (penalty == 0)
      {
        // A body without the split: its cells' pressures stay zero.
        compliance[row[0]] = inverse_schur[row[0]] = row_weight[row[0]] = 1;
        return;
      }
    compliance[row[0]]    = volume / penalty;
    inverse_schur[row[0]] = 1. / (volume * schur_compliance(material));
    double row_norm = 0;
    for (unsigned int i = 0; i < n; ++i)
      row_norm += divergence_integral[i] * divergence_integral[i];
    row_weight[row[0]] = std::sqrt(row_norm) * penalty / volume;
  }



  template <int dim>
  void
  VolumetricBlocks<dim>::finish_assembly(
    const TrilinosWrappers::SparseMatrix &stiffness,
    const AffineConstraints<double>      &constraints)
  {
    if (!active())
      return;
    reduced_stiffness.compress(VectorOperation::add);
    // A constrained row holds only a diagonal entry, which deal.II takes
    // from the cell matrices: make A's that of K, so that a displacement
    // with a non-zero entry there (a preconditioner's output) gets the same
    // residual from both forms.
    for (const auto i : stiffness.locally_owned_range_indices())
      if (constraints.is_constrained(i))
        reduced_stiffness.set(i, i, stiffness.diag_element(i));
    reduced_stiffness.compress(VectorOperation::insert);
    stiffness_bound = stiffness.linfty_norm(); // max_i sum_j |K_ij|
    divergence.compress(VectorOperation::add);
    compliance.compress(VectorOperation::insert);
    inverse_schur.compress(VectorOperation::insert);
    row_weight.compress(VectorOperation::insert);
  }



  template <int dim>
  VolumetricSplit
  VolumetricBlocks<dim>::split() const
  {
    if (!active())
      return {};
    return {&reduced_stiffness,
            &divergence,
            &compliance,
            &inverse_schur,
            &row_weight,
            stiffness_bound};
  }

  template <int dim>
  std::array<double, 2>
  VolumetricBlocks<dim>::reduced_lame_parameters(
    const ElasticConstants<dim> &material,
    const std::array<double, 2>      &of_stiffness)
  {
    if (penalty_modulus(material) == 0)
      return of_stiffness;
    const double G = material.shear_modulus;
    return {{reduced_bulk_modulus(material) - 2. * G / dim, G}};
  }



  template class VolumetricBlocks<2>;
  template class VolumetricBlocks<3>;
} // namespace FrictionalContact
