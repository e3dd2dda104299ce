// MeshRefinement's hanging vertices on a curved mesh (a ball, spherical
// manifold on its boundary), refined near one point: conform moves each
// hanging vertex to the mean of the vertices it hangs from, and restore puts
// it back exactly where refinement placed it, so that a mesh adapted after
// a restore equals one refined in one go (a checkpoint's, when loaded).
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>

#include <frictional_contact/model/mesh_refinement.h>

#include <algorithm>
#include <iostream>

using namespace FrictionalContact;

namespace
{
  template <int dim>
  void
  check()
  {
    parallel::distributed::Triangulation<dim> mesh(MPI_COMM_WORLD);
    GridGenerator::hyper_ball(mesh);
    mesh.refine_global(1);
    Point<dim> corner;
    corner[dim - 1] = -1;
    for (unsigned int i = 0; i < 2; ++i)
      {
        for (const auto &cell : mesh.active_cell_iterators())
          if (cell->is_locally_owned() && cell->center().distance(corner) < 0.8)
            cell->set_refine_flag();
        mesh.execute_coarsening_and_refinement();
      }
    const std::vector<Point<dim>> refined = mesh.get_vertices();

    MeshRefinement<dim>::conform_hanging_vertices(mesh);
    double       largest_move = 0;
    unsigned int moved        = 0;
    for (unsigned int v = 0; v < refined.size(); ++v)
      if (const double d = refined[v].distance(mesh.get_vertices()[v]); d > 0)
        {
          ++moved;
          largest_move = std::max(largest_move, d);
        }

    MeshRefinement<dim>::restore_hanging_vertices(mesh);
    double largest_difference = 0;
    for (unsigned int v = 0; v < refined.size(); ++v)
      largest_difference =
        std::max(largest_difference, refined[v].distance(mesh.get_vertices()[v]));

    std::cout << dim << "D: conform moved " << (moved > 0 ? "some" : "no")
              << " hanging vertices (largest move "
              << (largest_move > 1e-4 ? "> 1e-4" : "<= 1e-4")
              << "); restore put them back within "
              << (largest_difference <= 1e-15 ? "1e-15" : "MORE than 1e-15")
              << std::endl;
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
