#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <frictional_contact/solvers/contact_problem.h>
#include <frictional_contact/solvers/shifted_stiffness_solver.h>

#include <limits>
#include <string>

namespace FrictionalContact
{
  /**
   * When a method stops: its tolerance (each method says what it bounds)
   * and the iterations it may take per increment. Every method has the
   * entries "Tolerance" and "Maximum iterations" in its subsection.
   */
  struct StoppingRule
  {
    double       tolerance      = 0;
    unsigned int max_iterations = 0;

    /// Declares the two entries with the method's defaults and texts.
    static void
    declare_parameters(ParameterHandler  &prm,
                       const std::string &default_tolerance,
                       const std::string &tolerance_text,
                       const std::string &default_max_iterations,
                       const std::string &max_iterations_text);

    /// Reads them; a tolerance that is not positive is an InputError that
    /// names <Contact solver/@p subsection/Tolerance>.
    void
    parse_parameters(ParameterHandler &prm, const std::string &subsection);
  };



  /**
   * A method that solves one incremental contact problem. Methods register
   * themselves with FRICTIONAL_CONTACT_REGISTER_PLUGIN(ContactSolver, ...)
   * and are chosen by `Contact solver/Method`; each reads its parameters
   * from its own subsection of "Contact solver". All methods report the
   * same residuals and convergence history, so that they can be compared
   * side by side.
   */
  template <int dim>
  class ContactSolver
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    virtual ~ContactSolver() = default;

    virtual void
    parse_parameters(ParameterHandler &prm) = 0;

    /// One line for the run's header: the method and its main settings.
    virtual std::string
    describe() const = 0;

    /// What the method calls its iterations ("primal-dual", "Newton").
    virtual std::string
    iteration_name() const = 0;

    /// Whether the method needs mu_pi (problem.smallest_eigenvalue_K).
    virtual bool
    needs_smallest_eigenvalue() const
    {
      return false;
    }

    /// Whether the method solves problems of nonlinear laws
    /// (IncrementalProblem::nonlinear).
    virtual bool
    handles_nonlinear_laws() const
    {
      return false;
    }

    /// Whether the method solves problems whose K is singular on bodies
    /// that only contact holds (IncrementalProblem::contact_held).
    virtual bool
    handles_contact_held_bodies() const
    {
      return false;
    }

    /**
     * The largest ratio of the bodies' Young's moduli in a scene with
     * contact pairs for which the method reaches its tolerance (infinite:
     * any).
     */
    virtual double
    largest_modulus_ratio() const
    {
      return std::numeric_limits<double>::infinity();
    }

    /**
     * Whether the elastic solution of an increment is worth trying first
     * (<Contact solver/Try the elastic solution first>): a method that
     * converges slowly when nothing touches (Algorithm 2) says yes; one
     * that finds that out in its first iterations (Newton) says no, and
     * then also needs no length scale from it.
     */
    virtual bool
    wants_elastic_trial() const
    {
      return true;
    }

    /**
     * Whether an increment's solve gains from starting at the last
     * increment's motion (<Contact solver/Start from the last increment>
     * = auto): Newton's method, whose fast convergence starts nearer the
     * solution, says yes; Algorithm 2, which takes about as many
     * iterations from either start, says no and starts from no motion as
     * the paper does.
     */
    virtual bool
    gains_from_last_increment_start() const
    {
      return false;
    }

    /**
     * Solves @p problem. @p du and @p r hold the initial iterate on entry
     * and the last iterate on exit (whether or not it converged).
     */
    virtual SolveStatistics
    solve(const IncrementalProblem<dim> &problem,
          ShiftedStiffnessSolver        &linear_solver,
          Vector                        &du,
          std::vector<Tensor<1, dim>>   &r,
          const bool                     record_history) const = 0;

    const StoppingRule &
    stopping_rule() const
    {
      return stop;
    }

    /// Where progress lines go (every "Report every" iterations).
    void
    set_output(const ConditionalOStream &stream, const unsigned int every)
    {
      pcout        = &stream;
      report_every = every;
    }

  protected:
    StoppingRule stop;

    /// Prints a progress line for iteration @p k if one is due.
    void
    report(const unsigned int k, const HistoryRow &row) const;

    const ConditionalOStream *pcout        = nullptr;
    unsigned int              report_every = 0;
  };
} // namespace FrictionalContact
