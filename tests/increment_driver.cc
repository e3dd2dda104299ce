// The increment driver alone, without a mesh: the times of the loading
// history, and the on-failure policy (abort, or cut the failing increment
// in half up to Maximum cuts times in a row), with a stand-in increment
// that fails whenever it is longer than a given length.
#include <deal.II/base/mpi.h>

#include <frictional_contact/base/input.h>
#include <frictional_contact/driver/increment_driver.h>

#include <iostream>
#include <sstream>

using namespace FrictionalContact;

namespace
{
  /// Runs a driver on @p loading; increments longer than @p longest fail,
  /// the others take 2 iterations.
  void
  check(const std::string &title, const std::string &loading, const double longest)
  {
    ParameterHandler prm;
    IncrementDriver::declare_parameters(prm);
    prm.parse_input_from_string("subsection Loading\n" + loading + "\nend\n");
    IncrementDriver driver(prm);

    std::vector<unsigned int> solved;
    std::ostringstream        messages;
    std::string               outcome = "finished";
    try
      {
        driver.run(
          0,
          [&](const unsigned int l) {
            if (driver.times()[l] - driver.start_time(l) > longest * (1 + 1e-12))
              throw SolverError("too long");
            solved.push_back(l);
            return 2u;
          },
          messages);
      }
    catch (const SolverError &error)
      {
        outcome = std::string("stopped: ") + error.what();
      }
    std::cout << title << ": " << outcome << "; times";
    for (const double t : driver.times())
      std::cout << ' ' << t;
    unsigned int cut_lines = 0, grown_lines = 0;
    std::istringstream lines(messages.str());
    for (std::string line; std::getline(lines, line);)
      {
        cut_lines += line.rfind("Cut in half", 0) == 0;
        grown_lines += line.rfind("Grown", 0) == 0;
      }
    std::cout << "; " << solved.size() << " solved, " << cut_lines
              << " cut lines";
    if (grown_lines > 0)
      std::cout << ", " << grown_lines << " grown lines";
    std::cout << std::endl;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check("uniform", "set End time = 2\nset Number of increments = 4", 1);
  check("explicit times", "set Increment times = 0.1, 0.5, 2", 10);
  check("abort", "set Number of increments = 2", 0.3);
  check("cut once", "set Number of increments = 2\nset On failure = cut increment", 0.3);
  check("cut twice in a row",
        "set Number of increments = 1\nset On failure = cut increment", 0.3);
  check("too many cuts",
        "set Number of increments = 1\nset On failure = cut increment\n"
        "set Maximum cuts = 1",
        0.3);
  // Easy increments (2 iterations) let the cut ones grow back: 1 is cut
  // to 0.25, which passes; 0.25 to 0.5 merged with 0.5 to 1 fails and is
  // cut again; never past the history's own time 1 of the second case.
  check("cut increments grow back",
        "set Number of increments = 1\nset On failure = cut increment\n"
        "set Easy increment iterations = 2",
        0.3);
  check("growth stops at the history's times",
        "set Increment times = 0.5, 1\nset On failure = cut increment\n"
        "set Easy increment iterations = 2",
        0.3);
  // Grown past the history's times: each easy increment merges the next
  // two (0.25 + 0.25), never past the last time.
  check("growth past the history's times",
        "set Number of increments = 8\nset Easy increment iterations = 2\n"
        "set Grow past increment times = true",
        1);
  check("hard increments stay cut",
        "set Number of increments = 1\nset On failure = cut increment\n"
        "set Easy increment iterations = 1",
        0.3);
  check("cuts reset after a success",
        "set Increment times = 0.25, 1\nset On failure = cut increment\n"
        "set Maximum cuts = 2",
        0.25);
}
