// The contact operators of Kanno's examples at the paper's sizes: d and c
// (the paper: N_Y = 104 gives d = 54600, c = 260; N_Y = 28 in 3D gives
// d = 141288, c = 1624), sigma_T = 1 and T^T T = I for flat obstacles of
// any orientation, and each candidate owned by exactly one MPI rank.
#include <deal.II/base/mpi.h>

#include <frictional_contact/driver/simulator.h>

#include <iostream>

using namespace FrictionalContact;

namespace
{
  template <int dim>
  void
  check(const std::string &title, const std::string &scene)
  {
    ParameterHandler prm;
    Simulator<dim>::declare_parameters(prm);
    prm.parse_input_from_string(scene);
    Simulator<dim> simulator(prm, MPI_COMM_WORLD);
    simulator.setup();
    const ContactOperator<dim> &contact = simulator.get_model().get_contact();

    // Count the candidates again, by ownership: every rank adds its own.
    const auto owned_sum = Utilities::MPI::sum<types::global_dof_index>(
      contact.n_local(), MPI_COMM_WORLD);
    // The candidates expected from the geometry: vertices on the bottom
    // (y = 0 in 2D, z = 0 in 3D) that are not on the clamped face x = 0.
    unsigned int expected_here = 0;
    const IndexSet &owned = simulator.get_model().get_body().locally_owned_dofs();
    std::set<types::global_dof_index> seen;
    for (const auto &cell : simulator.get_model().get_body().get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            const auto &x = cell->vertex(v);
            const auto  g = cell->vertex_dof_index(v, 0);
            if (std::abs(x[dim - 1]) < 1e-12 && x[0] > 1e-12 &&
                owned.is_element(g) && seen.insert(g).second)
              ++expected_here;
          }
    const auto   expected = Utilities::MPI::sum(expected_here, MPI_COMM_WORLD);
    const double sigma_T  = contact.largest_singular_value();
    const double defect   = contact.orthonormality_defect();

    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << title << ": d = " << simulator.get_model().get_body().n_free_dofs()
                << ", c = " << contact.n_candidates()
                << ", candidates owned once: " << std::boolalpha
                << (owned_sum == contact.n_candidates())
                << ", c as the geometry says: "
                << (expected == contact.n_candidates())
                << ", sigma_T = " << sigma_T
                << ", T^T T = I: " << (defect < 1e-14) << std::endl
                << std::endl;
  }

  std::string
  example(const std::string &file, const std::string &extra)
  {
    return "include " SOURCE_DIR "/../parameters/" + file +
           "\nsubsection Postprocess\n subsection Visualization\n  set Write "
           "vtu = false\n  set Write csv tables = false\n end\nend\n"
           "subsection Output\n set Write "
           "statistics = false\nend\n" +
           extra;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check<2>("Example I, N_Y = 10", example("example1.prm", ""));
  check<2>("Example I, N_Y = 104",
           example("example1.prm",
                   "subsection Geometry\n subsection Box\n set X repetitions "
                   "= 260\n set Y repetitions = 104\n end\nend\n"));
  check<3>("Example II, N_Y = 4", example("example2.prm", ""));
  check<3>("Example II, N_Y = 28",
           example("example2.prm",
                   "subsection Geometry\n subsection Box\n set X repetitions "
                   "= 56\n set Y repetitions = 28\n set Z repetitions = 28\n "
                   "end\nend\n"));
  // A tilted floor: the frames are no longer the coordinate axes.
  check<3>("Example II, N_Y = 4, tilted floor",
           example("example2.prm",
                   "subsection Contact\n subsection Obstacle\n subsection "
                   "Plane\n set Outward normal = 0.3, -0.2, 1\n set Point = "
                   "0, 0, -0.5\n end\n end\nend\n"));
  check<2>("Example I, N_Y = 10, tilted floor",
           example("example1.prm",
                   "subsection Contact\n subsection Obstacle\n subsection "
                   "Plane\n set Outward normal = -0.4, 1\n set Point = "
                   "0, -0.5\n end\n end\nend\n"));
  return 0;
}
