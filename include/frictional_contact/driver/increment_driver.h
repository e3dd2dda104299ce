#pragma once

#include <deal.II/base/parameter_handler.h>

#include <frictional_contact/driver/loading_history.h>

#include <functional>
#include <memory>
#include <ostream>
#include <vector>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * Runs the loading history increment by increment: owns the end times
   * t_1 < ... < t_n of the increments and the policy for an increment that
   * fails (abort the run, or retry it as two halves, up to a number of cuts
   * in a row), for one that converged easily (the next two increments
   * that cuts made, or any two if asked, merged into one) and for one that
   * converged only in many iterations (the next one halved, and those
   * after it held to that length until one is easy). Owns the subsection
   * "Loading".
   * It knows nothing of meshes or solvers: an increment is a function of
   * its number, so that the policy can be tested alone.
   */
  class IncrementDriver
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    explicit IncrementDriver(ParameterHandler &prm);

    /// Solves increment l (from times()[l - 1], or 0, to times()[l]) and
    /// returns the contact solver's iterations; throws a SolverError if it
    /// fails.
    using Increment = std::function<unsigned int(const unsigned int l)>;

    /// Called after increment l once the times after it are settled (the
    /// policy applied), so that a checkpoint written there holds them.
    using Finished = std::function<void(const unsigned int l)>;

    /**
     * Runs increments @p first, first + 1, ... to the end. An increment that
     * throws a SolverError is retried as two halves, if the policy allows it
     * (one line on @p out says why), else the error goes on to the caller,
     * as does any other exception. After an increment that took at most
     * <Easy increment iterations>, the next two increments that cuts made
     * (or any two, with <Grow past increment times>) are merged into one
     * (one line on @p out): the increment grows. After one that took more
     * than <Hard increment iterations>, the next is held to its length
     * and halved (one line): the increment shrinks before an increment
     * fails. With that rule on, an increment that is not easy holds the
     * next one to its own length (one line where it splits it). Then
     * @p finished(l).
     */
    void
    run(const unsigned int first,
        const Increment   &increment,
        const Finished    &finished,
        std::ostream      &out);

    /// The end times of the increments: those of the loading history, with
    /// halves inserted where an increment failed and was cut.
    const std::vector<double> &
    times() const
    {
      return end_times;
    }

    /// The start time of increment @p l.
    double
    start_time(const unsigned int l) const
    {
      return l > 0 ? end_times[l - 1] : 0.;
    }

    /// The times of a checkpoint, which may hold cut increments.
    void
    restore_times(std::vector<double> times)
    {
      end_times = std::move(times);
    }

    const LoadingHistory &
    loading() const
    {
      return *history;
    }

  private:
    /// Applies the policy to the increments after increment @p l, solved in
    /// @p iterations: grows, halves or holds the next (one line on @p out
    /// if it did).
    void
    plan_after(const unsigned int l,
               const unsigned int iterations,
               std::ostream      &out);

    /// Merges increments @p l + 1 and @p l + 2 if a cut made the end time of
    /// the first (it is not one of the loading history's), or always with
    /// <Grow past increment times>; never past the last time. Returns
    /// whether it did.
    bool
    grow_after(const unsigned int l);

    /// Halves increment @p l + 1 unless it would be shorter than the
    /// loading history's own increment halved <Maximum cuts> times, or
    /// there is none. Returns whether it did.
    bool
    halve_after(const unsigned int l);

    /// Splits increment @p l + 1 evenly into pieces no longer than
    /// increment @p l, if it is longer. Returns whether it did.
    bool
    hold_after(const unsigned int l);

    /// Whether @p t is one of the loading history's own end times.
    bool
    planned(const double t) const;

    std::unique_ptr<LoadingHistory> history;
    /// The loading history's own end times, and those with the cuts.
    std::vector<double> planned_times;
    std::vector<double> end_times;
    bool                cut_on_failure;
    unsigned int        maximum_cuts;
    /// See <Loading/Easy increment iterations>; 0: never.
    unsigned int        easy_iterations;
    /// See <Loading/Grow past increment times>.
    bool                grow_past_times;
    /// See <Loading/Hard increment iterations>; 0: never.
    unsigned int        hard_iterations;
  };
} // namespace FrictionalContact
