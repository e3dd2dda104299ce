#include <deal.II/base/timer.h>

#include <frictional_contact/base/run_control.h>
#include <frictional_contact/base/plugins.h>
#include <frictional_contact/solvers/primal_dual_solver.h>
#include <frictional_contact/solvers/progress_rules.h>

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace FrictionalContact
{
  namespace
  {
    /**
     * The paper's stopping test, a small step, can pass far from a
     * solution: with a very large alpha_0, beta is tiny and du hardly
     * moves. A solve counts as converged only if the force balance
     * residual is also below this times the largest of |p|, |T r| and
     * |K du| (converged solves have about 1e-12).
     */
    constexpr double force_balance_guard = 1e-6;
  } // namespace



  template <int dim>
  void
  PrimalDualSolver<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Scaling",
                      "problem",
                      Patterns::Selection("problem|paper"),
                      "paper: Initial alpha and Tolerance are absolute, in "
                      "the units of the problem, as published (alpha_0 = 0.1 "
                      "and |du_{k+1} - du_k| <= 1e-12 for E = 1); the method "
                      "then depends on the units. problem: they are "
                      "dimensionless: alpha_0 = Initial alpha times the mean "
                      "normal stiffness of the contact nodes (t_n^T K t_n), "
                      "and the iteration stops when max |du_{k+1} - du_k| <= "
                      "Tolerance times the increment's length scale (largest "
                      "gap or displacement); the iterations then do not "
                      "depend on the units.");
    prm.declare_entry("Initial alpha",
                      "0.1",
                      Patterns::Double(0.),
                      "The dual step length alpha_0 of Algorithm 2 (> 0; see "
                      "Scaling); beta_0 = 1 / (alpha_0 sigma_T^2).");
    StoppingRule::declare_parameters(
      prm,
      "1e-12",
      "Stop when the step |du_{k+1} - du_k| is below this (see Scaling).",
      "100000",
      "Primal-dual iterations allowed per increment. A solve that needs "
      "more fails with its residuals.");
    prm.declare_entry("Stagnation window",
                      "10000",
                      Patterns::Integer(1),
                      "Stop with a failure when the step |du_k+1 - du_k| has "
                      "not become 1 percent smaller than its best value for "
                      "this many iterations, or when it grows to 1e8 times "
                      "its best value (divergence).");
    prm.declare_entry("Primal step tolerance",
                      "1e-4",
                      Patterns::Double(0., 1.),
                      "CG solves each primal step (beta K + I) du_{k+1} = b "
                      "for du_{k+1} - du_k until its residual is this factor "
                      "below the force residual p + T r - K du_k (times "
                      "beta). The paper's Matlab pcg was relative to |b| "
                      "instead, which stops CG, and with it the outer loop, "
                      "as soon as the step is below 1e-10 |b| (251 instead "
                      "of 292 iterations for example I at N_Y = 10). The "
                      "outer iterations of the paper's examples are the same "
                      "at 1e-6 and 1e-4, and within 0.7 % at 1e-3 "
                      "(doc/performance.md, \"Kanno's method\").");
    prm.declare_entry("Primal step start",
                      "extrapolated",
                      Patterns::Selection("extrapolated|previous iterate"),
                      "Where CG starts each primal step. previous iterate: "
                      "at du_k, as in the paper. extrapolated: at du_k + "
                      "2 (du_k - du_{k-1}) - (du_{k-1} - du_{k-2}), the "
                      "linear extrapolation of the last two steps, which "
                      "is within the tolerance for most steps of a long "
                      "run. Either start solves the same system to the same "
                      "tolerance.");
  }



  template <int dim>
  void
  PrimalDualSolver<dim>::parse_parameters(ParameterHandler &prm)
  {
    initial_alpha  = prm.get_double("Initial alpha");
    paper_scaling  = prm.get("Scaling") == "paper";
    this->stop.parse_parameters(prm, "Accelerated primal-dual");
    step_tolerance = prm.get_double("Primal step tolerance");
    extrapolate_start = prm.get("Primal step start") == "extrapolated";
    stagnation_window = prm.get_integer("Stagnation window");
    if (!(initial_alpha > 0))
      Input::fail("Contact solver/Accelerated primal-dual/Initial alpha",
                  Input::to_text(initial_alpha),
                  "a positive number is expected");
  }



  template <int dim>
  std::string
  PrimalDualSolver<dim>::describe() const
  {
    if (paper_scaling)
      return "accelerated primal-dual (Kanno, Algorithm 2), as published: "
             "alpha_0 = " +
             Input::to_text(initial_alpha) + ", stop at |du_k+1 - du_k| <= " +
             Input::to_text(this->stop.tolerance);
    return "accelerated primal-dual (Kanno, Algorithm 2), scaled: alpha_0 = " +
           Input::to_text(initial_alpha) +
           " k (k: normal stiffness of the contact nodes), stop at "
           "max |du_k+1 - du_k| <= " +
           Input::to_text(this->stop.tolerance) + " L";
  }



  template <int dim>
  SolveStatistics
  PrimalDualSolver<dim>::solve(const IncrementalProblem<dim> &problem,
                               ShiftedStiffnessSolver        &linear_solver,
                               Vector                        &du,
                               std::vector<Tensor<1, dim>>   &r,
                               const bool record_history) const
  {
    const Timer                 timer;
    const ContactMap<dim>      &contact = problem.contact;
    const unsigned int          c_local = contact.n_local();
    const std::vector<double>  &g       = problem.gaps;
    const unsigned int amg_setups_before = linear_solver.n_amg_setups;

    Vector du_hat(du), step(du), previous_step(du), K_du(du), T_r(du), rhs(du),
      scratch(du);
    problem.stiffness.vmult(K_du, du);

    // The step lengths and the stopping test, in the units of the problem
    // or (Scaling = problem) from its own scales.
    double alpha     = initial_alpha;
    double step_goal = this->stop.tolerance;
    if (!paper_scaling)
      {
        alpha *= mean_over_candidates(contact,
                                      contact_stiffness(problem, contact.normal_stiffness(problem.stiffness)),
                                      du.get_mpi_communicator());
        step_goal *= problem.length_scale;
      }
    double beta = 1. / (alpha * std::pow(problem.largest_singular_value_T, 2));

    SolveStatistics result;
    StepLengthWatch watch(stagnation_window);
    bool            small_step_out_of_balance = false;
    for (unsigned int k = 0; k < this->stop.max_iterations; ++k)
      {
        // Dual step (lines 4-7): modified gap, then projection onto F.
        for (unsigned int j = 0; j < c_local; ++j)
          {
            const Tensor<1, dim> u_j     = problem.relative_displacement(j, du);
            const Tensor<1, dim> u_hat_j = problem.relative_displacement(j, du_hat);
            // The modified gap; without friction it is the gap itself.
            const FrictionCone<dim> &cone = contact.friction_cone(j);
            const double g_tilde =
              cone.mu > 0 ? g[j] + cone.mu * FrictionCone<dim>::tangential_norm(u_j) :
                            g[j];
            Tensor<1, dim> s = r[j] - alpha * u_hat_j;
            s[0]             = r[j][0] + alpha * (g_tilde - u_hat_j[0]);
            r[j]             = cone.project(s);
          }
        contact.apply(r, T_r);

        // Primal step (lines 8-9) for the increment du_{k+1} - du_k:
        // (beta K + I) step = beta (p + T r - K du), i.e.
        // (K + I / beta) step = p + T r - K du.
        rhs = problem.load;
        rhs += T_r;
        rhs -= K_du;
        // CG starts from the paper's du_k (step 0) or from the linear
        // extrapolation 2 step_k - step_{k-1} of the last two steps, which
        // change slowly: CG then often needs one iteration or none.
        if (!extrapolate_start || k == 0)
          step = 0;
        else if (k == 1)
          previous_step = step;
        else
          {
            previous_step.sadd(-1., 2., step);
            step.swap(previous_step);
          }
        const unsigned int cg_iterations = linear_solver.solve(
          1. / beta, step, rhs, step_tolerance * rhs.l2_norm());
        result.linear_iterations += cg_iterations;

        // Acceleration (lines 10-12).
        const double theta = 1. / std::sqrt(1. + problem.smallest_eigenvalue_K * beta);
        alpha /= theta;
        beta *= theta;
        du += step;
        du_hat = du;
        du_hat.add(theta, step);

        problem.stiffness.vmult(K_du, du);
        result.iterations = k + 1;
        result.last_step  = paper_scaling ? step.l2_norm() : step.linfty_norm();
        result.residuals =
          compute_residuals(problem, du, K_du, T_r, r, scratch);

        const HistoryRow row{k + 1,
                             timer.wall_time(),
                             result.residuals,
                             result.last_step,
                             cg_iterations,
                             0,
                             0.};
        if (record_history)
          result.history.push_back(row);
        this->report(k + 1, row);
        RunControl::stop_if_urgent(du.get_mpi_communicator());

        if (!std::isfinite(result.last_step) || !result.residuals.finite())
          {
            result.failure = "NaN or infinity at iteration " +
                             std::to_string(k + 1) +
                             " (the iteration diverged); try smaller "
                             "increments or Method = semismooth Newton";
            break;
          }
        const StepLengthWatch::Verdict verdict = watch.record(k, result.last_step);
        if (verdict == StepLengthWatch::Verdict::diverged)
          {
            result.failure = "divergence at iteration " + std::to_string(k + 1) +
                             ": the step grew to " +
                             Input::to_text(result.last_step) + " from " +
                             Input::to_text(watch.best_step()) +
                             "; try smaller increments or Method = semismooth "
                             "Newton";
            break;
          }
        if (verdict == StepLengthWatch::Verdict::stagnated)
          {
            result.failure = "no progress from iteration " +
                             std::to_string(watch.last_progress_iteration() + 1) +
                             " to " + std::to_string(k + 1) + " (step " +
                             Input::to_text(result.last_step) + ", best " +
                             Input::to_text(watch.best_step()) +
                             "); try Method = semismooth Newton or smaller "
                             "increments";
            break;
          }
        if (result.last_step <= step_goal)
          {
            const double forces = std::max(
              {problem.load.l2_norm(), T_r.l2_norm(), K_du.l2_norm()});
            if (result.residuals.force_balance <= force_balance_guard * forces)
              {
                result.converged = true;
                break;
              }
            small_step_out_of_balance = true;
          }
      }
    if (!result.converged && result.failure.empty())
      result.failure = "no convergence in " + std::to_string(this->stop.max_iterations) +
                       " iterations (last |du_k+1 - du_k| = " +
                       Input::to_text(result.last_step) + ", tolerance " +
                       Input::to_text(step_goal) +
                       "); raise <Contact solver/Accelerated primal-dual/"
                       "Maximum iterations>" +
                       (small_step_out_of_balance ?
                          std::string(
                            ". The step fell below the tolerance, but the "
                            "force balance did not: <Initial alpha> is too "
                            "large for this problem") :
                          std::string());
    result.amg_setups = linear_solver.n_amg_setups - amg_setups_before;
    result.seconds    = timer.wall_time();
    return result;
  }

  FRICTIONAL_CONTACT_REGISTER_PLUGIN(
    ContactSolver,
    PrimalDualSolver,
    "accelerated primal-dual",
    "Kanno's Algorithm 2 as published: thousands of iterations, each a "
    "projection onto the friction cones and one CG solve with beta K + I.")
} // namespace FrictionalContact
