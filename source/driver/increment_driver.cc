#include <frictional_contact/base/input.h>
#include <frictional_contact/driver/increment_driver.h>

#include <algorithm>
#include <cmath>

namespace FrictionalContact
{
  void
  IncrementDriver::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Loading");
    LoadingHistory::declare_parameters(prm);
    prm.declare_entry("On failure",
                      "abort",
                      Patterns::Selection("abort|cut increment"),
                      "What a failed increment does (no convergence, "
                      "divergence, stagnation): abort the run, with the "
                      "residuals, keeping the finished increments; or cut "
                      "increment: retry it as two halves, up to Maximum "
                      "cuts times in a row.");
    prm.declare_entry("Maximum cuts",
                      "5",
                      Patterns::Integer(0, 30),
                      "How often in a row an increment may be cut in half.");
    prm.declare_entry("Easy increment iterations",
                      "0",
                      Patterns::Integer(0),
                      "After an increment whose contact solve took at most "
                      "this many iterations, the next two increments that "
                      "cuts made (On failure = cut increment) are merged "
                      "into one: the increment doubles back towards the "
                      "loading history's own, never past its times (unless "
                      "Grow past increment times). 0: cut increments stay "
                      "cut.");
    prm.declare_entry("Grow past increment times",
                      "false",
                      Patterns::Bool(),
                      "true: after an easy increment (Easy increment "
                      "iterations) the next two increments are merged even "
                      "where the loading history's own times part them, so "
                      "an increment grows to twice the planned one: fewer "
                      "solves where the problem is easy, and results written "
                      "at fewer times. The last time is always kept.");
    prm.declare_entry("Hard increment iterations",
                      "0",
                      Patterns::Integer(0),
                      "After an increment whose contact solve took more "
                      "than this many iterations, the next increment is "
                      "held to its length and halved before it is tried, "
                      "down to the loading history's own increment halved "
                      "Maximum cuts times: "
                      "shorter increments where the solve grew hard, before "
                      "one fails. The increments after it are held to the "
                      "last one's length (split evenly where longer) until "
                      "an easy one (Easy increment iterations) lets them "
                      "grow back. Must exceed Easy increment iterations. 0: "
                      "never.");
    prm.leave_subsection();
  }



  IncrementDriver::IncrementDriver(ParameterHandler &prm)
  {
    prm.enter_subsection("Loading");
    history        = std::make_unique<LoadingHistory>(prm);
    cut_on_failure = prm.get("On failure") == "cut increment";
    maximum_cuts   = prm.get_integer("Maximum cuts");
    easy_iterations = prm.get_integer("Easy increment iterations");
    grow_past_times = prm.get_bool("Grow past increment times");
    hard_iterations = prm.get_integer("Hard increment iterations");
    prm.leave_subsection();
    if (hard_iterations > 0 && hard_iterations <= easy_iterations)
      throw InputError("<Loading/Hard increment iterations> = " +
                       std::to_string(hard_iterations) + " is not above "
                       "<Loading/Easy increment iterations> = " +
                       std::to_string(easy_iterations) + ": an increment "
                       "would be both easy and hard; raise the first or "
                       "lower the second");
    planned_times = history->increment_times();
    end_times     = planned_times;
  }



  void
  IncrementDriver::run(const unsigned int first,
                       const Increment   &increment,
                       const Finished    &finished,
                       std::ostream      &out)
  {
    unsigned int cuts = 0;
    for (unsigned int l = first; l < end_times.size(); ++l)
      try
        {
          const unsigned int iterations = increment(l);
          cuts                          = 0;
          plan_after(l, iterations, out);
          finished(l);
        }
      catch (const SolverError &error)
        {
          if (!cut_on_failure || cuts == maximum_cuts)
            throw;
          // Retry from the same state with half the increment.
          end_times.insert(end_times.begin() + l,
                           (start_time(l) + end_times[l]) / 2);
          ++cuts;
          out << "Cut in half (" << cuts << " of at most " << maximum_cuts
              << " cuts in a row), now " << end_times.size()
              << " increments, because " << error.what() << std::endl;
          --l;
        }
  }



  void
  IncrementDriver::plan_after(const unsigned int l,
                              const unsigned int iterations,
                              std::ostream      &out)
  {
    const bool easy = easy_iterations > 0 && iterations <= easy_iterations;
    const bool hard = hard_iterations > 0 && iterations > hard_iterations;
    // The start of the line that says how the times changed, if they did.
    std::string what;
    if (easy)
      {
        // The time a merge would take away, if one of the history's.
        const std::string skipped =
          l + 1 < end_times.size() && planned(end_times[l + 1]) ?
            "Grown past t = " + Input::to_text(end_times[l + 1]) :
            "Grown back";
        if (grow_after(l))
          what = skipped;
      }
    else if (hard_iterations > 0)
      {
        // Held to this increment's length, and halved after a hard one.
        const bool held = hold_after(l);
        if (hard && halve_after(l))
          what = "Halved ahead";
        else if (held)
          what = "Held at the last length";
      }
    if (!what.empty())
      out << what << " (increment " << l + 1 << " took " << iterations
          << " iterations), now " << end_times.size() << " increments"
          << std::endl;
  }



  bool
  IncrementDriver::grow_after(const unsigned int l)
  {
    if (l + 2 >= end_times.size())
      return false;
    if (!grow_past_times && planned(end_times[l + 1]))
      return false;
    end_times.erase(end_times.begin() + l + 1);
    return true;
  }



  bool
  IncrementDriver::halve_after(const unsigned int l)
  {
    if (l + 1 >= end_times.size())
      return false;
    // The history's own increment that holds the next one.
    const double end = end_times[l + 1];
    const auto   planned_end =
      std::lower_bound(planned_times.begin(), planned_times.end(), end);
    const double planned_start =
      planned_end == planned_times.begin() ? 0. : *(planned_end - 1);
    const double half = (end - end_times[l]) / 2;
    if (half < (*planned_end - planned_start) / (1u << maximum_cuts) * (1 - 1e-12))
      return false;
    end_times.insert(end_times.begin() + l + 1, end_times[l] + half);
    return true;
  }



  bool
  IncrementDriver::hold_after(const unsigned int l)
  {
    if (l + 1 >= end_times.size())
      return false;
    const double length      = end_times[l] - start_time(l);
    const double next_length = end_times[l + 1] - end_times[l];
    if (next_length <= length * (1 + 1e-12))
      return false;
    // Into pieces of equal length, none longer than the last increment.
    const double pieces = std::ceil(next_length / length * (1 - 1e-12));
    end_times.insert(end_times.begin() + l + 1,
                     end_times[l] + next_length / pieces);
    return true;
  }



  bool
  IncrementDriver::planned(const double t) const
  {
    return std::find(planned_times.begin(), planned_times.end(), t) !=
           planned_times.end();
  }
} // namespace FrictionalContact
