#include <frictional_contact/base/input.h>
#include <frictional_contact/fclib/fclib_newton.h>
#include <frictional_contact/fclib/newton_systems.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <memory>

namespace FrictionalContact
{
  using namespace dealii;

  namespace
  {
    /// Iterates the line search compares with (non-monotone).
    constexpr unsigned int line_search_memory = 5;
    /// Up to this many contact unknowns (m), the Newton steps work on the
    /// condensed system (one LU of M, a dense m x m LU per step), above it
    /// on the coupled one (a sparse LU of size n + m per step).
    constexpr unsigned int largest_condensed_size = 400;

    std::unique_ptr<NewtonSystem>
    newton_system(const FclibProblem &problem)
    {
      if (problem.spacedim * problem.n_contacts() <= largest_condensed_size)
        if (auto condensed = CondensedSystem::create(problem))
          return condensed;
      return std::make_unique<CoupledSystem>(problem);
    }
  } // namespace



  FclibNewton::FclibNewton(const FclibProblem &problem)
    : problem(problem)
  {}



  FclibNewton::Result
  FclibNewton::solve(const double tolerance, const unsigned int max_iterations) const
  {
    const auto   start = std::chrono::steady_clock::now();
    const std::unique_ptr<NewtonSystem> newton = newton_system(problem);
    NewtonSystem                       &system = *newton;
    Result       result;

    Vector<double>                  x(system.size()), F(x), dx(x), trial(x), F_trial(x);
    std::vector<LocalLinearization> local, local_trial;
    double                          merit = system.residual(x, F, local);
    std::deque<double>              recent_merits{merit};
    for (unsigned int k = 0;; ++k)
      {
        result.iterations = k;
        result.solution   = system.solution(x);
        result.error      = fclib_error(problem, result.solution);
        if (!std::isfinite(result.error))
          {
            result.failure = "the iterate is not finite after " +
                             std::to_string(k) + " Newton iterations";
            break;
          }
        if (result.error <= tolerance)
          {
            result.converged = true;
            break;
          }
        if (k == max_iterations)
          {
            result.failure = "no convergence in " + std::to_string(k) +
                             " Newton iterations (FCLIB error " +
                             Input::scientific(result.error) + ", tolerance " +
                             Input::scientific(tolerance) +
                             "); raise <Contact solver/Semismooth Newton/"
                             "Maximum iterations>";
            break;
          }

        if (!system.newton_step(local, F, dx))
          {
            result.failure = "the Newton system is singular at iteration " +
                             std::to_string(k + 1) + " (FCLIB error " +
                             Input::scientific(result.error) + ")";
            break;
          }

        // Backtracking on |F|^2 against the largest of the recent values;
        // the best trial is taken when none is good enough.
        const double reference =
          *std::max_element(recent_merits.begin(), recent_merits.end());
        double best_merit = std::numeric_limits<double>::infinity(), best_step = 1;
        for (double step = 1; step > 1e-6; step /= 2)
          {
            trial = x;
            trial.add(step, dx);
            const double trial_merit = system.residual(trial, F_trial, local_trial);
            if (trial_merit < best_merit)
              {
                best_merit = trial_merit;
                best_step  = step;
              }
            if (trial_merit <= (1 - 1e-4 * step) * reference)
              break;
          }
        x.add(best_step, dx);
        merit = system.residual(x, F, local);
        recent_merits.push_back(merit);
        if (recent_merits.size() > line_search_memory)
          recent_merits.pop_front();
      }
    result.seconds = std::chrono::duration<double>(
                       std::chrono::steady_clock::now() - start)
                       .count();
    return result;
  }
} // namespace FrictionalContact
