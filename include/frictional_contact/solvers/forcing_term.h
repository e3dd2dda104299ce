#pragma once

#include <algorithm>
#include <cmath>
#include <string>

namespace FrictionalContact
{
  /**
   * The forcing term eta_k of an inexact Newton method: the factor by which
   * the Krylov solver reduces the residual of the k-th Newton system. Owns
   * eta; the caller gives the nonlinear residual norms of each step.
   *
   * - fixed: eta = the largest forcing term, ten times smaller after a step
   *   the line search had to shorten (down to 1e-4, as below), ten times
   *   larger again (up to the largest) after a full step.
   * - Eisenstat-Walker (1996, their choice 2, gamma = 0.9, alpha = 2):
   *   eta_k = gamma (|F_k| / |F_k-1|)^alpha, safeguarded by gamma
   *   eta_k-1^alpha when that exceeds 0.1, so that eta does not fall
   *   faster than the convergence can follow, and kept within [1e-8, the
   *   largest forcing term]; after a step the line search shortened (the
   *   direction was poor), ten times smaller than the smaller of that and
   *   the forcing term before, so that shortened steps in a row tighten
   *   the solves as the fixed rule does (extreme_aspect_50_newton took 27
   *   Newton steps instead of 15 without this), down to 1e-4 (or the
   *   largest forcing term, where that is smaller): below that a
   *   shortened step's direction is poor because stick/slip states switch
   *   along it, not because its solve was loose (the 3D bracket's crawls
   *   with friction took up to 515 Krylov iterations per step at 1e-8 and
   *   still moved a sixty-fourth of the step). (Limiting its growth to
   *   ten times a step, as in the fixed rule, cost example II 40 % more
   *   Krylov iterations and did not prevent the stall of cattaneo_3d:
   *   doc/performance.md.) When the caller sees no progress for a few
   *   steps, it calls fall_back(): from then on the fixed rule, ten times
   *   tighter, since loose directions can keep moving stick/slip fronts
   *   changing without end.
   */
  class ForcingTerm
  {
  public:
    enum class Rule
    {
      fixed,
      eisenstat_walker
    };

    ForcingTerm(const Rule rule, const double largest)
      : rule(rule)
      , largest(largest)
      , eta(largest)
    {}

    /// The rule named as in <Contact solver/Semismooth Newton/Forcing term>.
    static Rule
    rule_from_name(const std::string &name)
    {
      return name == "Eisenstat-Walker" ? Rule::eisenstat_walker : Rule::fixed;
    }

    /// The forcing term of the next Newton system.
    double
    current() const
    {
      return eta;
    }

    /**
     * Records an accepted step: @p norm is the nonlinear residual norm at
     * the new iterate, @p previous_norm at the one before, @p full_step
     * whether the line search took the whole step.
     */
    void
    record(const double previous_norm, const double norm, const bool full_step)
    {
      if (rule == Rule::fixed || !(previous_norm > 0) || !std::isfinite(norm))
        eta = full_step ? std::min(10 * eta, largest) : 0.1 * eta;
      else
        {
          const double ratio     = norm / previous_norm;
          const double safeguard = gamma * eta * eta;
          const double before    = eta;
          eta                    = gamma * ratio * ratio;
          if (safeguard > 0.1)
            eta = std::max(eta, safeguard);
          eta = std::min(eta, largest);
          if (!full_step)
            eta = 0.1 * std::min(eta, before);
        }
      eta = std::max(eta,
                     full_step ? smallest :
                                 std::min(smallest_after_shortened_step, largest));
    }

    /**
     * Gives up the Eisenstat-Walker rule for the rest of the solve: the
     * fixed rule with a ten times smaller largest forcing term. Called when
     * the nonlinear iteration has made no progress for some steps.
     */
    void
    fall_back()
    {
      if (rule == Rule::fixed)
        return;
      rule    = Rule::fixed;
      largest = 0.1 * largest;
      eta     = std::min(eta, largest);
    }

  private:
    static constexpr double gamma                         = 0.9;
    static constexpr double smallest                      = 1e-8;
    static constexpr double smallest_after_shortened_step = 1e-4;
    Rule                    rule;
    double                  largest;
    double                  eta;
  };
} // namespace FrictionalContact
