#include <deal.II/base/timer.h>

#include <frictional_contact/base/run_control.h>
#include <frictional_contact/base/plugins.h>
#include <frictional_contact/solvers/semismooth_newton_solver.h>

#include "semismooth_newton_iteration.h"

#include <algorithm>
#include <limits>
#include <sstream>

namespace FrictionalContact
{
  template <int dim>
  void
  SemismoothNewtonSolver<dim>::declare_parameters(ParameterHandler &prm)
  {
    StoppingRule::declare_parameters(
      prm,
      "1e-10",
      "Stop when the paper's three residuals, with the reactions projected "
      "onto the friction cones, are small: force balance below this times "
      "|p|, penetration below this times the length scale L (the largest gap "
      "or displacement), complementarity below this times |p| L. Each term "
      "of the complementarity sum is non-negative for reactions in the cone, "
      "so the sum measures every node. For an FCLIB problem (--fclib): stop "
      "when FCLIB's error measure is below this.",
      "100",
      "Newton iterations allowed per increment.");
    prm.declare_entry("Tangential parameter",
                      "0.1",
                      Patterns::Double(0.),
                      "c_t,j = this times c_j in zeta = r_t - c_t u_t. A node "
                      "whose stick/slip state keeps changing gets a c_t ten "
                      "times smaller, twice at most: a large c_t makes the "
                      "slip direction flip back and forth, a small one "
                      "decides by the force, and one far smaller sorts a node "
                      "that slides by a force a hair inside the cone.");
    prm.declare_entry("Linear reduction",
                      "0.1",
                      Patterns::Double(0., 1.),
                      "The largest forcing term: CG (or GMRES) reduces the "
                      "residual of a Newton system by at most this factor "
                      "(see Forcing term); a tenth of it with the geometric "
                      "multigrid, a hundredth for a B-bar body (measured, "
                      "doc/performance.md).");
    prm.declare_entry(
      "Preconditioner",
      "AMG with node conditions",
      Patterns::Selection("AMG with node conditions|AMG of K"),
      "The preconditioner of the Newton systems. AMG with node conditions: "
      "the AMG of K with stiff springs in the directions the node conditions "
      "hold and the Robin term across slips, its coarse levels made again "
      "(cheaply) when the conditions change; its Krylov iterations per "
      "Newton step hardly grow with the mesh or the slip set. AMG of K: the "
      "AMG of K alone, built once, blind to the conditions (about four "
      "times the Krylov iterations on Kanno's example II; "
      "doc/performance.md). Both follow <Linear solver/Preconditioner>: "
      "with Jacobi, the diagonal of K.");
    prm.declare_entry("Forcing term",
                      "Eisenstat-Walker",
                      Patterns::Selection("fixed|Eisenstat-Walker"),
                      "How much CG (or GMRES) reduces the residual of each "
                      "Newton system. Eisenstat-Walker: by 0.9 (|F_k|/"
                      "|F_k-1|)^2 (their choice 2, safeguarded, at most "
                      "Linear reduction), with |F| the line search's merit; "
                      "after a shortened step ten times less than the "
                      "smaller of that and the previous term, down to 1e-4; "
                      "after " +
                        std::to_string(SemismoothNewton::steps_before_fall_back) +
                        " steps without progress, the fixed rule with a "
                        "tenth of Linear reduction. fixed: by Linear "
                        "reduction, ten times more after a step the line "
                        "search had to shorten (down to 1e-4). Measured "
                        "(doc/performance.md): 40 % fewer Krylov iterations "
                        "than fixed on example II.");
  }



  template <int dim>
  void
  SemismoothNewtonSolver<dim>::parse_parameters(ParameterHandler &prm)
  {
    this->stop.parse_parameters(prm, "Semismooth Newton");
    linear_reduction = prm.get_double("Linear reduction");
    forcing_rule = ForcingTerm::rule_from_name(prm.get("Forcing term"));
    tangential_factor = prm.get_double("Tangential parameter");
    preconditioner_sees_conditions =
      prm.get("Preconditioner") == "AMG with node conditions";
  }



  template <int dim>
  std::string
  SemismoothNewtonSolver<dim>::describe() const
  {
    return "semismooth Newton (primal-dual active set), tolerance " +
           Input::to_text(this->stop.tolerance);
  }



  template <int dim>
  SolveStatistics
  SemismoothNewtonSolver<dim>::solve(const IncrementalProblem<dim> &problem,
                                     ShiftedStiffnessSolver &linear_solver,
                                     Vector                 &du,
                                     std::vector<Tensor<1, dim>> &r,
                                     const bool record_history) const
  {
    using namespace SemismoothNewton;
    const Timer                           timer;
    const ContactMap<dim>                &contact = problem.contact;
    const bool has_friction = contact.largest_friction_coefficient() > 0;
    const unsigned int n        = contact.n_local();
    const MPI_Comm     comm     = du.get_mpi_communicator();
    const unsigned int setups   = linear_solver.n_amg_setups;
    linear_solver.prepare_stiffness_preconditioner();

    // The scale c_j of the complementarity functions: the contact's
    // normal stiffness from K's diagonal, or for a nearly incompressible
    // body from that of the split's reduced stiffness. K's carries the
    // bulk modulus, thousands of times the shear modulus at nu = 0.4999,
    // and c_j that large let the gaps of inexact Newton steps decide the
    // normal sets, which then cycle.
    // The preconditioner's springs take the node's own (they stand for
    // its conditions in the matrix of its own body).
    const VolumetricSplit *volumetric = linear_solver.volumetric_split();
    const std::vector<double> own_stiffness = contact.normal_stiffness(
      volumetric != nullptr ?
        static_cast<const StiffnessOperator &>(
          AssembledStiffness(*volumetric->reduced_stiffness)) :
        problem.stiffness);
    const std::vector<double> c = contact_stiffness(problem, own_stiffness);

    std::vector<double> initial_c_t(n);
    for (unsigned int j = 0; j < n; ++j)
      initial_c_t[j] = tangential_factor * c[j];
    ActiveSets<dim>                  sets(initial_c_t);
    const std::vector<NodeCondition> &conditions = sets.conditions;

    // From a cold start, the frictionless problem first: the normal sets
    // settle in a few steps, and friction then starts from real pressures.
    const bool cold_start = !any_reaction(r, comm);
    bool       friction   = has_friction && !cold_start;

    const double load_norm = problem.load.l2_norm();
    const double tolerance = std::max(this->stop.tolerance, problem.tolerance);
    NewtonWorkspace<dim> work(du, n);
    // Without candidates (a nonlinear body that touches nothing) any
    // positive scale serves the merit's force balance.
    const double mean_c =
      contact.n_candidates() > 0 ? mean_over_candidates(contact, c, comm) : 1.;
    // The merit's weights of the force balance: 1 / K_ii, of the matrix
    // the c_j come from.
    TrilinosWrappers::MPI::Vector balance_weight(du);
    for (const types::global_dof_index i : balance_weight.locally_owned_elements())
      {
        const double K_ii = volumetric != nullptr ?
                              volumetric->reduced_stiffness->diag_element(i) :
                              problem.stiffness.diag_element(i);
        balance_weight[i] = K_ii > 0 ? 1. / K_ii : 1. / mean_c;
      }
    balance_weight.compress(VectorOperation::insert);
    // From a warm start (du != 0), a nonlinear law's tangent is taken there:
    // now, or once the first Newton step's preconditioner is made
    // (NonlinearStiffness::preconditioner_from_start()).
    const bool warm = du.linfty_norm() > 0;
    bool       tangent_after_preconditioner =
      warm && problem.nonlinear != nullptr && problem.nonlinear->preconditioner_from_start();
    problem.internal_force(du, work.K_du, warm && !tangent_after_preconditioner);
    contact.apply(r, work.T_r);
    SolveStatistics           result;
    const NodeProjection<dim> P(contact, conditions, problem.gap_slopes);
    // A nearly incompressible body's Newton steps need tighter solves: with
    // the forcing terms of a compressible one, the normal sets of Hertz 2D
    // at nu = 0.4999 cycle (doc/performance.md, "Nearly incompressible").
    // So do those preconditioned by the geometric multigrid: with ML's
    // forcing terms they took 19 to 34 Newton steps on example II at
    // N_Y = 24 instead of 13 (doc/performance.md, "Geometric multigrid").
    const double scale_of_forcing =
      volumetric != nullptr ? 0.01 :
      linear_solver.newton_uses_geometric_multigrid() ? 0.1 : 1.;
    ForcingTerm forcing(forcing_rule, scale_of_forcing * linear_reduction);
    ConditionPreconditioner<dim> preconditioner(linear_solver,
                                                contact,
                                                preconditioner_sees_conditions,
                                                problem.contact_held.stabilization,
                                                comm);
    MeritWatch                progress;
    // The line search's merit at the current iterate.
    double                    merit         = 0;
    unsigned int              steps_blocked = 0;
    // The force balance of the iterate before the current one, and whether
    // the current one still lacks a nonlinear law's tangent
    // (likely_last_step()).
    double force_balance_before = 0;
    bool   tangent_due          = false;

    for (unsigned int k = 0; k < this->stop.max_iterations; ++k)
      {
        // Frames that follow the configuration are taken at the iterate,
        // and its residuals with them.
        if (k > 0 && problem.geometry)
          {
            problem.geometry->follow(du, r, work.K_du);
            contact.apply(r, work.T_r);
            result.residuals = admissible_residuals(
              problem, du, work.K_du, r, work.admissible_r, work.scratch, work.w);
          }
        // Done when the residuals of the current iterate are small.
        if (k > 0 && meets(tolerance, problem, du, work.K_du, result.residuals))
          {
            result.converged = true;
            result.loosened  = tolerance > this->stop.tolerance;
            break;
          }
        if (tangent_due)
          {
            problem.internal_force(du, work.K_du, true);
            tangent_due = false;
          }

        // Sort the nodes by the augmented reactions of the current iterate;
        // once the normal sets of the frictionless start have settled, sort
        // them again with friction.
        unsigned int changes = Utilities::MPI::sum(
          classify(problem, du, r, c, friction, sets), comm);
        if (!friction && has_friction && changes == 0 && k > 0)
          {
            friction = true;
            progress.restart(k);
            changes = Utilities::MPI::sum(
              classify(problem, du, r, c, true, sets), comm);
          }
        if (problem.contact_held.any())
          {
            if (k == 0 && cold_start)
              changes += Utilities::MPI::sum(
                activate_nearest_nodes(problem, du, sets), comm);
            if (const std::string body = body_left_without_contact(
                  problem.contact_held, conditions, comm);
                !body.empty())
              {
                result.failure =
                  "only contact holds the body '" + body + "', and Newton "
                  "iteration " + std::to_string(k + 1) + " leaves it no node in "
                  "contact: its load pulls it away from what it touches, and "
                  "there is no equilibrium; hold it with <Boundary "
                  "conditions/Fixed boundaries>, or change its load";
                break;
              }
          }

        // The preconditioner for the new conditions, if they changed.
        if (preconditioner.update(sets, own_stiffness, friction, comm))
          ++result.amg_updates;
        if (tangent_after_preconditioner)
          {
            problem.internal_force(du, work.K_du, true);
            tangent_after_preconditioner = false;
          }

        // The linear problem: du = du_D + w, with du_D meeting the node
        // conditions and w in the subspace where they are homogeneous.
        remember_iterate(problem, du, r, work);
        unsigned int linear_iterations = 0;
        const double forcing_term      = forcing.current();
        const bool   last_likely       = likely_last_step(tolerance, problem, du, work.K_du,
                                                  result.residuals, force_balance_before,
                                                  forcing_term, changes);
        try
          {
            linear_iterations =
              solve_linearized(problem, sets, P, preconditioner, linear_solver, friction,
                               r, forcing_term,
                               // The nonlinear residual at the iterate, as a
                               // force: the merit's energy times a stiffness.
                               k > 0 ? std::sqrt(mean_c * merit) :
                                       std::numeric_limits<double>::infinity(),
                               // The stopping rule's force: p, or K du where an
                               // obstacle drives the body without a load.
                               0.1 * tolerance *
                                 std::max({load_norm,
                                           work.K_du.l2_norm(),
                                           problem.nonlinear != nullptr ?
                                             problem.nonlinear->force_scale() :
                                             0.}),
                               du, work.K_du, work.rhs, work.w);
          }
        catch (const SolverControl::NoConvergence &e)
          {
            result.failure =
              linear_failure(k, e, linear_solver.maximum_iterations());
            break;
          }
        result.linear_iterations += linear_iterations;

        work.inverted_cell.clear();
        const LineSearchStep step = search_along_step(
          problem, conditions, c, sets.c_t, friction, mean_c, balance_weight, du, r, work,
          !last_likely);
        // A shortened step took the tangent where it stopped.
        tangent_due = last_likely && step.t == 1;
        // A NaN merit would accept every step (its comparisons are false).
        if (std::isnan(step.merit_before) || std::isnan(step.merit_after))
          {
            result.failure = "NaN in the line search's merit at Newton iteration " +
                             std::to_string(k + 1);
            break;
          }
        merit = step.merit_after;
        forcing.record(std::sqrt(step.merit_before),
                       std::sqrt(step.merit_after),
                       step.t == 1);
        // Steps blocked where they would invert a cell, in a row and
        // without progress, do not get past it (a cell that folds in
        // every state ahead): stop after a few rather than a whole window.
        steps_blocked = work.inverted_cell.empty() ? 0 : steps_blocked + 1;
        const bool stalled = progress.stalled(k, step.merit_after);
        if (stalled || (steps_blocked >= steps_before_fall_back &&
                        k >= progress.last_progress_step() + steps_before_fall_back))
          {
            result.failure =
              stall_failure(progress.last_progress_step(), k, work.inverted_cell);
            break;
          }
        if (k >= progress.last_progress_step() + steps_before_fall_back)
          forcing.fall_back();

        work.previous_du -= du;
        result.iterations = k + 1;
        result.last_step  = work.previous_du.l2_norm();
        force_balance_before = result.residuals.force_balance;
        result.residuals  = admissible_residuals(
          problem, du, work.K_du, r, work.admissible_r, work.scratch, work.w);
        HistoryRow row{k + 1,
                       timer.wall_time(),
                       result.residuals,
                       result.last_step,
                       linear_iterations,
                       changes,
                       forcing_term};
        if (record_history)
          {
            row.active_nodes = Utilities::MPI::sum<types::global_dof_index>(
              std::count_if(conditions.begin(), conditions.end(),
                            [](const NodeCondition c) { return c != NodeCondition::none; }),
              comm);
            row.plastic_points =
              problem.nonlinear != nullptr ? problem.nonlinear->plastic_points() : 0;
          }
        if (record_history)
          result.history.push_back(row);
        this->report(k + 1, row);
        RunControl::stop_if_urgent(comm);
        if (!result.residuals.finite())
          {
            result.failure = "NaN or infinity at Newton iteration " +
                             std::to_string(k + 1);
            break;
          }
      }
    r = work.admissible_r;
    if (!result.converged && result.failure.empty())
      result.failure = "no convergence in " +
                       std::to_string(this->stop.max_iterations) +
                       " Newton iterations; raise <Contact solver/Semismooth "
                       "Newton/Maximum iterations> or use smaller increments";
    result.amg_setups = linear_solver.n_amg_setups - setups;
    result.seconds    = timer.wall_time();
    return result;
  }

  FRICTIONAL_CONTACT_REGISTER_PLUGIN(
    ContactSolver,
    SemismoothNewtonSolver,
    "semismooth Newton",
    "A primal-dual active set (semismooth Newton) method: per iteration "
    "one linear elastic solve with the contact conditions imposed by "
    "projection, the friction force coupled to the normal reaction at "
    "slipping nodes, CG or GMRES preconditioned by the AMG of K, and a line "
    "search.")
} // namespace FrictionalContact
