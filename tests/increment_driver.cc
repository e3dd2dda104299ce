// The increment driver alone, without a mesh: the times of the loading
// history, the on-failure policy (abort, or cut the failing increment in
// half up to Maximum cuts times in a row), and the increments that grow
// after easy ones, shrink after hard ones and hold their length after
// the others, with a stand-in increment that fails whenever it is longer
// than a given length and takes 10 iterations when longer than another;
// and that each increment is finished (its checkpoint written) with the
// times after it settled.
#include <deal.II/base/mpi.h>

#include <frictional_contact/base/input.h>
#include <frictional_contact/driver/increment_driver.h>

#include <iostream>
#include <memory>
#include <sstream>

using namespace FrictionalContact;

namespace
{
  /// Runs a driver on @p loading; increments longer than @p longest fail,
  /// those longer than @p hard take 10 iterations, the others 2. With
  /// @p show_finished, the number of increments as each was finished.
  void
  check(const std::string &title,
        const std::string &loading,
        const double       longest,
        const double       hard          = 1e10,
        const bool         show_finished = false)
  {
    ParameterHandler prm;
    IncrementDriver::declare_parameters(prm);
    prm.parse_input_from_string("subsection Loading\n" + loading + "\nend\n");
    std::unique_ptr<IncrementDriver> made;
    try
      {
        made = std::make_unique<IncrementDriver>(prm);
      }
    catch (const InputError &error)
      {
        std::cout << title << ": refused: " << error.what() << std::endl;
        return;
      }
    IncrementDriver &driver = *made;

    std::vector<unsigned int> solved;
    std::vector<std::size_t>  n_when_finished;
    std::ostringstream        messages;
    std::string               outcome = "finished";
    try
      {
        driver.run(
          0,
          [&](const unsigned int l) {
            const double length = driver.times()[l] - driver.start_time(l);
            if (length > longest * (1 + 1e-12))
              throw SolverError("too long");
            solved.push_back(l);
            return length > hard * (1 + 1e-12) ? 10u : 2u;
          },
          [&](const unsigned int) {
            n_when_finished.push_back(driver.times().size());
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
    unsigned int cut_lines = 0, grown_lines = 0, halved_lines = 0,
                 held_lines = 0;
    std::istringstream lines(messages.str());
    for (std::string line; std::getline(lines, line);)
      {
        cut_lines += line.rfind("Cut in half", 0) == 0;
        grown_lines += line.rfind("Grown", 0) == 0;
        halved_lines += line.rfind("Halved ahead", 0) == 0;
        held_lines += line.rfind("Held at the last length", 0) == 0;
      }
    std::cout << "; " << solved.size() << " solved, " << cut_lines
              << " cut lines";
    if (grown_lines > 0)
      std::cout << ", " << grown_lines << " grown lines";
    if (halved_lines > 0)
      std::cout << ", " << halved_lines << " halved lines";
    if (held_lines > 0)
      std::cout << ", " << held_lines << " held lines";
    if (show_finished)
      {
        std::cout << "; increments when each was finished:";
        for (const std::size_t n : n_when_finished)
          std::cout << ' ' << n;
      }
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
  // Hard increments (longer than 0.3: 10 iterations) halve the next one:
  // 0 to 0.5 is hard, so 0.5 to 1 is tried as 0.5 to 0.75 and 0.75 to 1.
  check("a hard increment halves the next",
        "set Number of increments = 2\nset Hard increment iterations = 5", 10, 0.3);
  // Halved down to the history's increment halved Maximum cuts times
  // (0.25 of 0.5), not below: 0.75 to 1 stays whole.
  check("halving stops at Maximum cuts",
        "set Number of increments = 2\nset Hard increment iterations = 5\n"
        "set Maximum cuts = 1",
        10,
        0.1);
  // Shrinking and growing in turn: 0 to 0.5 is hard, so 0.5 to 1 is
  // halved; 0.5 to 0.75 is easy, so 0.75 to 1 and 1 to 1.5 are merged;
  // 0.75 to 1.5 is hard, so 1.5 to 2 is halved.
  check("shrunk where hard, grown where easy",
        "set End time = 2\nset Number of increments = 4\n"
        "set Hard increment iterations = 5\nset Easy increment iterations = 2\n"
        "set Grow past increment times = true",
        10,
        0.3);
  // The increments after a halved one keep its length while neither easy
  // nor hard (2 iterations, no Easy increment iterations): 0 to 0.5 is
  // hard, 0.5 to 0.75 is not, so 1 to 1.5 and 1.5 to 2 are held to 0.25;
  // each increment is finished with the times after it settled.
  check("hard increments hold the shortened length",
        "set End time = 2\nset Number of increments = 4\n"
        "set Hard increment iterations = 5",
        10,
        0.3,
        true);
  // A hard increment halves the next as held to its own length: 0 to 0.25
  // is hard, so 0.25 to 1 is held to 0.25 and halved to 0.125.
  check("halved from the hard increment's length",
        "set Increment times = 0.25, 1\nset Hard increment iterations = 5", 10, 0.2);
  // Held evenly: 0.3 to 0.65 is split in two halves of 0.175, no sliver.
  check("held evenly",
        "set Increment times = 0.3, 0.65\nset Hard increment iterations = 5", 10);
  check("hard not above easy",
        "set Hard increment iterations = 2\nset Easy increment iterations = 2", 1);
}
