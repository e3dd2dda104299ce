#pragma once

#include <limits>

namespace FrictionalContact
{
  /**
   * When Algorithm 2 gives up, from the length of its steps: it has
   * stagnated when the best step has not become 1 percent smaller for
   * more than a window of iterations, and diverged when a step grows to
   * 1e8 times the best one. Owns the best step and the iteration of the
   * last progress.
   */
  class StepLengthWatch
  {
  public:
    explicit StepLengthWatch(const unsigned int window)
      : window(window)
    {}

    enum class Verdict
    {
      going_on,
      diverged,
      stagnated
    };

    /// Records the step of iteration @p k (counted from 0).
    Verdict
    record(const unsigned int k, const double step)
    {
      if (step < 0.99 * best)
        {
          best          = step;
          last_progress = k;
        }
      if (step > 1e8 * best)
        return Verdict::diverged;
      if (k - last_progress > window)
        return Verdict::stagnated;
      return Verdict::going_on;
    }

    double
    best_step() const
    {
      return best;
    }

    /// The iteration (from 0) of the last new best step.
    unsigned int
    last_progress_iteration() const
    {
      return last_progress;
    }

  private:
    unsigned int window;
    double       best          = std::numeric_limits<double>::max();
    unsigned int last_progress = 0;
  };



  /**
   * When the semismooth Newton method gives up: its merit function must
   * fall by a tenth of its best value within 25 steps; the same rule, over
   * a longer window, for the residual of a Krylov solve of its Newton
   * systems (StagnationControl). Owns the best merit and the step of the
   * last progress.
   */
  class MeritWatch
  {
  public:
    explicit MeritWatch(const unsigned int window = 25)
      : window(window)
    {}

    /// Forgets the merits before step @p k (the method changed its
    /// equations there: friction switched on).
    void
    restart(const unsigned int k)
    {
      best_merit    = std::numeric_limits<double>::max();
      last_progress = k;
    }

    /// Records the merit of step @p k; true if it has stalled.
    bool
    stalled(const unsigned int k, const double merit)
    {
      if (merit < 0.9 * best_merit)
        {
          best_merit    = merit;
          last_progress = k;
        }
      return k > last_progress + window;
    }

    /// The step (from 0) of the last new best merit.
    unsigned int
    last_progress_step() const
    {
      return last_progress;
    }

  private:
    unsigned int window;
    double       best_merit    = std::numeric_limits<double>::max();
    unsigned int last_progress = 0;
  };
} // namespace FrictionalContact
