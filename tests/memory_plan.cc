// MeshRefinement's memory plan, which the memory check and the automatic
// choice of the solver path (Model, <Linear solver/Preconditioner> = auto)
// share: with a budget of 8 GB, a 3D mesh of 1e5 cells fits with K
// assembled, one of 1e6 cells only with K matrix-free (so auto takes that
// path), one of 1e7 cells with neither; in 2D the paths plan the same
// memory per cell, so auto never switches. The machines' own figure is
// read (MemAvailable, one rank per machine) and positive.
#include <deal.II/base/mpi.h>

#include <frictional_contact/model/mesh_refinement.h>

#include <iostream>

using namespace FrictionalContact;

namespace
{
  template <int dim>
  void
  check()
  {
    const double budget = 8e9;
    for (const double n_cells : {1e5, 1e6, 1e7})
      std::cout << dim << "D, " << n_cells << " cells: "
                << (MeshRefinement<dim>::bytes_needed(n_cells, false) <= budget ?
                      "fits with K assembled" :
                    MeshRefinement<dim>::fits_only_matrix_free(n_cells, budget) ?
                      "fits only with K matrix-free" :
                      "fits with neither")
                << std::endl;
    std::cout << dim << "D, no budget known: "
              << (MeshRefinement<dim>::fits_only_matrix_free(1e6, 0) ?
                    "switches" :
                    "keeps the path")
              << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check<2>();
  check<3>();
  std::cout << "the available memory is "
            << (MeshRefinement<3>::available_memory(MPI_COMM_WORLD) > 0 ?
                  "known" :
                  "unknown")
            << std::endl;
}
