// MeshRefinement's memory plan, which the memory check and the automatic
// choice of the solver path (Model, <Linear solver/Preconditioner> = auto)
// share: with 10 GB available, a 3D mesh of 1e5 cells fits with K
// assembled, one of 1e6 cells only with K matrix-free (so auto takes that
// path), one of 1e7 cells with neither; in 2D the paths plan the same
// memory per cell, so auto never switches. The machine's own figure is
// read (MemAvailable) and positive.
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
    const double available = 10e9;
    for (const double n_cells : {1e5, 1e6, 1e7})
      std::cout << dim << "D, " << n_cells << " cells: "
                << (MeshRefinement<dim>::bytes_needed(n_cells, false) <=
                        MeshRefinement<dim>::largest_share * available ?
                      "fits with K assembled" :
                    MeshRefinement<dim>::fits_only_matrix_free(n_cells, available) ?
                      "fits only with K matrix-free" :
                      "fits with neither")
                << std::endl;
    std::cout << dim << "D, nothing known available: "
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
  std::cout << "this machine's available memory is "
            << (MeshRefinement<3>::available_memory(MPI_COMM_WORLD) > 0 ?
                  "known" :
                  "unknown")
            << std::endl;
}
