// The rules by which the contact solvers give up, on made-up sequences
// (doc/robustness.md, "When a solve fails"): Algorithm 2 stops when a step
// grows to 1e8 times its best (divergence) or when the best step has not
// become 1 percent smaller for more than <Stagnation window> iterations;
// the Newton method stops when its merit has not fallen by a tenth within
// 25 steps. Real runs reach the stagnation rules (errors/stagnation_*);
// no run of a convergent Algorithm 2 diverges, so that rule is checked
// here only.
#include <frictional_contact/solvers/progress_rules.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <string>

using namespace FrictionalContact;

namespace
{
  const char *
  name(const StepLengthWatch::Verdict verdict)
  {
    switch (verdict)
      {
        case StepLengthWatch::Verdict::diverged:
          return "diverged";
        case StepLengthWatch::Verdict::stagnated:
          return "stagnated";
        default:
          return "going on";
      }
  }

  /// Feeds the steps step(k), k = 0, 1, ..., to a watch with @p window and
  /// prints the first iteration at which it gives up, if any.
  void
  watch_steps(const std::string                        &title,
              const unsigned int                        window,
              const std::function<double(unsigned int)> &step)
  {
    StepLengthWatch watch(window);
    for (unsigned int k = 0; k < 1000; ++k)
      {
        const StepLengthWatch::Verdict verdict = watch.record(k, step(k));
        if (verdict != StepLengthWatch::Verdict::going_on)
          {
            std::cout << title << ": " << name(verdict) << " at iteration "
                      << k + 1 << ", best step " << watch.best_step()
                      << " at iteration " << watch.last_progress_iteration() + 1
                      << std::endl;
            return;
          }
      }
    std::cout << title << ": going on after 1000 iterations" << std::endl;
  }

  /// The same for the Newton method's merits.
  void
  watch_merits(const std::string                        &title,
               const std::function<double(unsigned int)> &merit,
               const unsigned int                         restart_at = 0)
  {
    MeritWatch watch;
    for (unsigned int k = 0; k < 1000; ++k)
      {
        if (restart_at > 0 && k == restart_at)
          watch.restart(k);
        if (watch.stalled(k, merit(k)))
          {
            std::cout << title << ": stalled at step " << k + 1
                      << ", last progress at step "
                      << watch.last_progress_step() + 1 << std::endl;
            return;
          }
      }
    std::cout << title << ": going on after 1000 steps" << std::endl;
  }
} // namespace

int
main()
{
  // Steps that halve: never stop.
  watch_steps("halving steps", 10, [](unsigned int k) {
    return std::pow(0.5, k % 1000);
  });
  // Constant steps: the first is the best; stagnated once the window has
  // passed without a new best.
  watch_steps("constant steps, window 10", 10, [](unsigned int) { return 1.; });
  // A step 1e9 times the best one at iteration 21: divergence.
  watch_steps("blow-up at iteration 21", 100, [](unsigned int k) {
    return k == 20 ? 1e9 * std::pow(0.5, 19) : std::pow(0.5, k);
  });
  // Up to 1e8 times is still tolerated (then it stagnates).
  watch_steps("growth by 1e7 at iteration 21", 30, [](unsigned int k) {
    return k < 20 ? std::pow(0.5, k) : 1e7 * std::pow(0.5, 19);
  });

  // Merits that halve: never stall.
  watch_merits("halving merits", [](unsigned int k) {
    return std::pow(0.5, k % 1000);
  });
  // Merits that stop falling after step 10: stalled 25 steps later.
  watch_merits("merits flat from step 10", [](unsigned int k) {
    return std::pow(0.5, std::min(k, 9u));
  });
  // Falling by 5 percent a step: by a tenth only every other step, fine.
  watch_merits("merits falling 5 percent a step", [](unsigned int k) {
    return std::pow(0.95, k % 1000);
  });
  // A restart at step 20 forgets the best merit: flat merits stall 25 steps
  // after the restart, not after the start.
  watch_merits("flat merits, restart at step 20",
               [](unsigned int) { return 1.; }, 20);
  return 0;
}
