// IncrementDrive tells whether an increment goes on the way the last one
// went, the condition for starting its solve from the last increment's
// motion: on a lifting split over the ranks and the other parts of a
// drive, a die that presses on goes on (also in a shorter increment, at
// the same pace); one that turns to slide, reverses, stops, starts
// moving, or changes its pace by more than a factor 2 turns; a part still
// in both increments does not count; drives on different rows, or without
// a last increment, never go on.
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/trilinos_vector.h>

#include <frictional_contact/driver/increment_drive.h>

#include <iostream>
#include <string>

using namespace FrictionalContact;

namespace
{
  using Vector = TrilinosWrappers::MPI::Vector;

  /// A lifting of @p n entries split evenly over the ranks: each owned
  /// entry i is a + b i (a prescribed motion along and across a face).
  Vector
  lifting(const unsigned int n, const double a, const double b)
  {
    const MPI_Comm     comm  = MPI_COMM_WORLD;
    const unsigned int ranks = Utilities::MPI::n_mpi_processes(comm);
    const unsigned int rank  = Utilities::MPI::this_mpi_process(comm);
    IndexSet           owned(n);
    owned.add_range(rank * n / ranks, (rank + 1) * n / ranks);
    Vector v(owned, comm);
    for (const auto i : owned)
      v[i] = a + b * i;
    v.compress(VectorOperation::insert);
    return v;
  }

  /// A drive of the lifting (a, b) and a tool moved by @p tool (x, z).
  IncrementDrive<2>
  drive(const double a, const double b, const double tool_x, const double tool_z,
        const unsigned int n = 12)
  {
    return IncrementDrive<2>(lifting(n, a, b),
                             {{0.}, {0., 0.}, {tool_x, tool_z}, {0.}});
  }

  void
  report(const std::string &what, const bool result)
  {
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << what << ": " << (result ? "goes on" : "turns") << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const IncrementDrive<2> pressing = drive(0, 0, 0, -0.1);
  report("pressing on", drive(0, 0, 0, -0.1).continues(pressing, 1, 1));
  report("pressing on in half the time", drive(0, 0, 0, -0.05).continues(pressing, 0.5, 1));
  report("pressing on, turned by 20 degrees",
         drive(0, 0, 0.1 * std::sin(0.349), -0.1 * std::cos(0.349)).continues(pressing, 1, 1));
  report("turned to slide", drive(0, 0, 0.2, 0).continues(pressing, 1, 1));
  report("pressing back", drive(0, 0, 0, 0.1).continues(pressing, 1, 1));
  report("stopped", drive(0, 0, 0, 0).continues(pressing, 1, 1));
  report("three times the pace", drive(0, 0, 0, -0.3).continues(pressing, 1, 1));
  const IncrementDrive<2> pulling = drive(1, 0.1, 0, 0);
  report("the face pulled on", drive(2, 0.2, 0, 0).continues(pulling, 2, 1));
  report("the face pulled on, the die starting to move",
         drive(1, 0.1, 0, -0.1).continues(pulling, 1, 1));
  report("the face pulled back", drive(-1, -0.1, 0, 0).continues(pulling, 1, 1));
  report("the face pulled across instead",
         drive(1, -0.3, 0, 0).continues(pulling, 1, 1));
  report("on other rows", drive(0, 0, 0, -0.1, 14).continues(pressing, 1, 1));
  report("after no increment", drive(0, 0, 0, -0.1).continues(IncrementDrive<2>(), 1, 1));
}
