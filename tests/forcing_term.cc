// The forcing terms of the Newton method's linear solves
// (<Contact solver/Semismooth Newton/Forcing term>), on made-up residual
// sequences: the fixed rule tightens ten times after a shortened step
// (down to 1e-4, or the largest term where that is smaller) and relaxes
// again after full steps; Eisenstat-Walker's choice 2 follows the
// square of the residual ratio, is held up by its safeguard while it is
// large, is ten times smaller after a shortened step (and shortened steps
// in a row tighten it further, as the fixed rule does, down to 1e-4),
// never exceeds the largest forcing term and never falls below 1e-8;
// falling back gives the fixed rule with a tenth of the largest term.
#include <frictional_contact/solvers/forcing_term.h>

#include <iostream>
#include <string>
#include <vector>

using namespace FrictionalContact;

namespace
{
  struct Step
  {
    double residual;
    bool   full;
    bool   then_fall_back = false;
  };

  /// Prints the forcing term before each step and after the last.
  void
  follow(const std::string       &title,
         const ForcingTerm::Rule  rule,
         const double             largest,
         const double             first_residual,
         const std::vector<Step> &steps)
  {
    ForcingTerm forcing(rule, largest);
    double      previous = first_residual;
    std::cout << title << ":";
    for (const Step &step : steps)
      {
        std::cout << ' ' << forcing.current();
        forcing.record(previous, step.residual, step.full);
        if (step.then_fall_back)
          forcing.fall_back();
        previous = step.residual;
      }
    std::cout << ' ' << forcing.current() << std::endl;
  }
} // namespace

int
main()
{
  using Rule = ForcingTerm::Rule;
  std::cout.precision(4);
  follow("fixed, a shortened step then full steps",
         Rule::fixed,
         1e-2,
         1.,
         {{0.5, false}, {0.4, true}, {0.1, true}, {0.01, true}});
  follow("fixed, shortened steps down to the floor",
         Rule::fixed,
         1e-2,
         1.,
         std::vector<Step>(8, {1., false}));
  // A largest term below the floor of shortened steps: it stays there.
  follow("fixed, a largest term below that floor",
         Rule::fixed,
         1e-5,
         1.,
         std::vector<Step>(3, {1., false}));
  // Quadratic convergence: eta falls with the square of the ratio, down to
  // the floor (the safeguard 0.9 eta^2 acts at the first step only).
  follow("Eisenstat-Walker, quadratic convergence",
         Rule::eisenstat_walker,
         0.5,
         1.,
         {{0.5, true}, {0.1, true}, {1e-3, true}, {1e-7, true}, {1e-15, true}});
  // A ratio of 0.8 asks for 0.576, a growing residual for more: the
  // largest term.
  follow("Eisenstat-Walker, the largest term",
         Rule::eisenstat_walker,
         0.5,
         1.,
         {{0.8, true}, {1.6, true}, {1.52, true}});
  // After eta = 0.45 the safeguard 0.9 * 0.45^2 = 0.18 > 0.1 keeps eta from
  // falling to 0.9 * 0.01^2 at once.
  follow("Eisenstat-Walker, the safeguard",
         Rule::eisenstat_walker,
         0.5,
         1.,
         {{0.7071, true}, {0.007071, true}, {7.071e-5, true}});
  follow("Eisenstat-Walker, a shortened step",
         Rule::eisenstat_walker,
         0.5,
         1.,
         {{0.9, false}, {0.8, true}});
  // Each shortened step gives a tenth of what its ratio asks for; the next
  // full step what its ratio asks for.
  follow("Eisenstat-Walker, shortened steps",
         Rule::eisenstat_walker,
         0.5,
         1.,
         {{0.9, false}, {0.85, false}, {0.7, true}, {0.6, true}});
  // The safeguard holds eta at 0.225 after the first step, then the floor.
  follow("Eisenstat-Walker, the floor",
         Rule::eisenstat_walker,
         0.5,
         1.,
         {{1e-6, true}, {1e-14, true}});
  // Shortened steps in a row: a tenth each, down to 1e-4.
  follow("Eisenstat-Walker, shortened steps down to their floor",
         Rule::eisenstat_walker,
         0.5,
         1.,
         std::vector<Step>(5, {0.99, false}));
  // Falling back after the first step: the fixed rule with a tenth of the
  // largest term, 0.05, ten times smaller after a shortened step, never
  // above 0.05 again. The fixed rule does not fall back further.
  follow("Eisenstat-Walker, falling back",
         Rule::eisenstat_walker,
         0.5,
         1.,
         {{0.9, true, true}, {0.1, true}, {0.09, false}, {0.05, true},
          {0.04, true}});
  follow("fixed, falling back",
         Rule::fixed,
         1e-2,
         1.,
         {{0.9, true, true}, {0.5, true}});
  std::cout << "rule from name: "
            << (ForcingTerm::rule_from_name("Eisenstat-Walker") ==
                Rule::eisenstat_walker)
            << (ForcingTerm::rule_from_name("fixed") == Rule::fixed)
            << std::endl;
}
