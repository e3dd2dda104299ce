// CellMatrixPositions adds cell matrices into a Trilinos matrix by cached
// positions: on a mesh with hanging vertices and a fixed boundary, split
// over the ranks, a matrix assembled with the positions where a cell has
// them (and AffineConstraints elsewhere) equals one assembled through
// AffineConstraints only, to round-off; both paths are taken; and the
// positions of a cell refuse dofs other than those they were taken for.
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/numerics/vector_tools.h>

#include <frictional_contact/model/cell_matrix_positions.h>

#include <cmath>
#include <iostream>

using namespace FrictionalContact;

namespace
{
  template <int dim>
  void
  check()
  {
    const MPI_Comm                            comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<dim> mesh(comm);
    GridGenerator::hyper_cube(mesh, 0, 1, /*colorize=*/true);
    mesh.refine_global(2);
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->is_locally_owned() && cell->center()[0] < 0.3)
        cell->set_refine_flag();
    mesh.execute_coarsening_and_refinement();

    const FESystem<dim> fe(FE_Q<dim>(1), dim);
    DoFHandler<dim>     dof_handler(mesh);
    dof_handler.distribute_dofs(fe);
    const IndexSet owned    = dof_handler.locally_owned_dofs();
    IndexSet       relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    AffineConstraints<double> constraints(relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    VectorTools::interpolate_boundary_values(dof_handler, 2, Functions::ZeroFunction<dim>(dim),
                                             constraints);
    constraints.close();

    TrilinosWrappers::SparsityPattern sparsity(owned, owned, relevant, comm);
    DoFTools::make_sparsity_pattern(dof_handler, sparsity, constraints, false,
                                    Utilities::MPI::this_mpi_process(comm));
    sparsity.compress();
    TrilinosWrappers::SparseMatrix by_constraints, by_positions;
    by_constraints.reinit(sparsity);
    by_positions.reinit(sparsity);

    CellMatrixPositions<dim> positions;
    positions.update(dof_handler, constraints, by_positions);
    // Twice, as a tangent is assembled at every Newton step: the second
    // update keeps the positions of the first.
    unsigned int with_positions = 0, without = 0;
    for (unsigned int pass = 0; pass < 2; ++pass)
      {
        positions.update(dof_handler, constraints, by_positions);
        std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
        FullMatrix<double>                   cell_matrix(dofs.size(), dofs.size());
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              cell->get_dof_indices(dofs);
              for (unsigned int i = 0; i < dofs.size(); ++i)
                for (unsigned int j = 0; j < dofs.size(); ++j)
                  cell_matrix(i, j) =
                    std::sin(1. + i + 3. * j + 7. * cell->center()[0] + 5. * cell->center()[1]);
              constraints.distribute_local_to_global(cell_matrix, dofs, by_constraints);
              const unsigned int c = cell->active_cell_index();
              if (positions.has(c, dofs))
                {
                  positions.add(c, cell_matrix);
                  ++with_positions;
                }
              else
                {
                  constraints.distribute_local_to_global(cell_matrix, dofs, by_positions);
                  ++without;
                }
            }
        by_constraints.compress(VectorOperation::add);
        by_positions.compress(VectorOperation::add);
      }
    // Positions never serve a cell with other dofs than they were taken
    // for (as after a change of the mesh the fingerprint missed).
    bool refuses_other_dofs = true;
    {
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() && positions.has(cell->active_cell_index(), [&] {
              cell->get_dof_indices(dofs);
              return dofs;
            }()))
          {
            std::swap(dofs[0], dofs[1]);
            refuses_other_dofs =
              refuses_other_dofs && !positions.has(cell->active_cell_index(), dofs);
          }
    }
    refuses_other_dofs = Utilities::MPI::min(refuses_other_dofs ? 1 : 0, comm) == 1;
    const double norm = by_constraints.frobenius_norm();
    by_positions.add(-1., by_constraints);
    const double difference = by_positions.frobenius_norm() / norm;
    with_positions          = Utilities::MPI::sum(with_positions, comm);
    without                 = Utilities::MPI::sum(without, comm);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      std::cout << dim << "D: cells added by positions: " << (with_positions > 0 ? "some" : "none")
                << ", through the constraints: " << (without > 0 ? "some" : "none")
                << "; the two matrices differ by "
                << (difference <= 1e-14 ? "at most 1e-14" : "MORE than 1e-14")
                << " (relative, Frobenius); positions refuse a cell's dofs in another order: "
                << (refuses_other_dofs ? "yes" : "NO") << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check<2>();
  check<3>();
  return 0;
}
