#pragma once

#include <deal.II/base/mpi.h>

#include <frictional_contact/base/input.h>
#include <frictional_contact/solvers/progress_rules.h>
#include <frictional_contact/solvers/semismooth_newton_solver.h>

#include "semismooth_newton_linearization.h"
#include "semismooth_newton_merit.h"
#include "semismooth_newton_preconditioner.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace FrictionalContact
{
  /**
   * The steps of one iteration of SemismoothNewtonSolver besides its
   * building blocks (semismooth_newton_linearization.h): the node
   * conditions imposed on the iterate, the linear problem solved, the
   * residuals and the stopping rule, the line search along the step, and
   * the messages of a solve that fails.
   */
  namespace SemismoothNewton
  {
    /**
     * Moves du onto the node conditions: the normal part of every active
     * node to its gap, the tangential part of sticking nodes to the
     * obstacle's slip. Returns whether a node of this rank slips.
     */
    template <int dim>
    bool
    impose_node_conditions(const IncrementalProblem<dim>     &problem,
                           const std::vector<NodeCondition> &conditions,
                           TrilinosWrappers::MPI::Vector    &du,
                           double                           &largest_move)
    {
      bool any_slip = false;
      largest_move  = 0;
      for (unsigned int j = 0; j < conditions.size(); ++j)
        {
          if (conditions[j] == NodeCondition::none)
            continue;
          const Tensor<1, dim> current = problem.contact.local_part(j, du);
          Tensor<1, dim>       target  = current;
          if (conditions[j] == NodeCondition::all_fixed)
            for (unsigned int d = 1; d < dim; ++d)
              target[d] = problem.obstacle_slip[j][d];
          target[0] = problem.closing_normal(j, target - problem.obstacle_slip[j]);
          largest_move = std::max(largest_move, (target - current).norm());
          problem.contact.add_reaction(j, target - current, du);
          if (conditions[j] == NodeCondition::normal_fixed)
            any_slip = true;
        }
      return any_slip;
    }



    /**
     * The slipping nodes' terms of the right-hand side: the friction force
     * coupled to the normal reaction and the Robin term across the slip
     * direction, - B (du_D - the obstacle's slip).
     */
    template <int dim>
    void
    add_slip_terms(const IncrementalProblem<dim>       &problem,
                   const ContactStiffness<dim>         &A,
                   const ActiveSets<dim>               &sets,
                   const TrilinosWrappers::MPI::Vector &du,
                   TrilinosWrappers::MPI::Vector       &rhs)
    {
      A.couple(rhs);
      A.add_robin(du, -1., rhs);
      if (dim < 3)
        return;
      for (unsigned int j = 0; j < sets.conditions.size(); ++j)
        if (sets.conditions[j] == NodeCondition::normal_fixed)
          {
            Tensor<1, dim> slip = problem.obstacle_slip[j];
            slip -= (slip * sets.slip_direction[j]) * sets.slip_direction[j];
            problem.contact.add_reaction(j, sets.robin[j] * slip, rhs);
          }
    }



    /**
     * The reactions: the residual K du - p (in @p K_du_minus_p) at the
     * active nodes, zero elsewhere. They may leave the cones on the way;
     * the residuals judge their projection onto the cones.
     */
    template <int dim>
    void
    active_reactions(const ContactMap<dim>               &contact,
                     const std::vector<NodeCondition>   &conditions,
                     const TrilinosWrappers::MPI::Vector &K_du_minus_p,
                     std::vector<Tensor<1, dim>>         &r)
    {
      for (unsigned int j = 0; j < conditions.size(); ++j)
        r[j] = conditions[j] == NodeCondition::none ?
                 Tensor<1, dim>() :
                 contact.local_part(j, K_du_minus_p);
    }



    /**
     * For each body only contact holds, makes its candidates nearest to
     * contact active (their gap within a small tolerance of the body's
     * smallest): the first Newton matrix then holds it where it will touch,
     * instead of leaving it free (K singular). For a cold start; returns
     * how many nodes of this rank it made active.
     */
    template <int dim>
    unsigned int
    activate_nearest_nodes(const IncrementalProblem<dim> &problem,
                           const Vector                  &du,
                           ActiveSets<dim>               &sets)
    {
      const ContactHeldBodies &held = problem.contact_held;
      const unsigned int       n_bodies = held.names.size();
      std::vector<double> smallest(n_bodies, std::numeric_limits<double>::max());
      std::vector<double> gap(sets.conditions.size());
      for (unsigned int j = 0; j < gap.size(); ++j)
        {
          gap[j] = problem.gap_at(j, problem.relative_displacement(j, du));
          for (unsigned int b = 0; b < n_bodies; ++b)
            if (held.held_by_candidate[j] & (std::uint64_t(1) << b))
              smallest[b] = std::min(smallest[b], gap[j]);
        }
      Utilities::MPI::min(smallest, du.get_mpi_communicator(), smallest);
      unsigned int activated = 0;
      for (unsigned int j = 0; j < gap.size(); ++j)
        for (unsigned int b = 0; b < n_bodies; ++b)
          if ((held.held_by_candidate[j] & (std::uint64_t(1) << b)) &&
              sets.conditions[j] == NodeCondition::none &&
              gap[j] <= smallest[b] +
                          1e-8 * std::max(std::abs(smallest[b]), problem.length_scale))
            {
              sets.conditions[j] = NodeCondition::normal_fixed;
              ++activated;
            }
      return activated;
    }



    /// The first body only contact holds that the node conditions leave
    /// without any node in contact, or an empty name. Collective.
    inline std::string
    body_left_without_contact(const ContactHeldBodies          &held,
                              const std::vector<NodeCondition> &conditions,
                              const MPI_Comm                    comm)
    {
      std::vector<unsigned int> touching(held.names.size(), 0);
      for (unsigned int j = 0; j < conditions.size(); ++j)
        if (conditions[j] != NodeCondition::none)
          for (unsigned int b = 0; b < touching.size(); ++b)
            if (held.held_by_candidate[j] & (std::uint64_t(1) << b))
              touching[b] = 1;
      Utilities::MPI::max(touching, comm, touching);
      for (unsigned int b = 0; b < touching.size(); ++b)
        if (touching[b] == 0)
          return held.names[b];
      return "";
    }



    /// Whether any candidate on any rank has a reaction (a warm start).
    template <int dim>
    bool
    any_reaction(const std::vector<Tensor<1, dim>> &r, const MPI_Comm comm)
    {
      double largest = 0;
      for (const auto &r_j : r)
        largest = std::max(largest, r_j.norm());
      return Utilities::MPI::max(largest, comm) > 0;
    }



    /// The step of the line search and the merits at both ends.
    struct LineSearchStep
    {
      double t;
      double merit_before;
      double merit_after;
    };

    /**
     * The step t along the segment from the previous iterate: halved from
     * 1 (down to 1/64) until the merit drops enough.
     */
    template <int dim>
    LineSearchStep
    line_search(const MeritAlongStep<dim> &merit)
    {
      LineSearchStep step{1., merit(0.), merit(1.)};
      while (step.t > 1. / 64 &&
             step.merit_after > (1 - 1e-4 * step.t) * step.merit_before)
        {
          step.t /= 2;
          step.merit_after = merit(step.t);
        }
      return step;
    }

    /// The largest residual, relative to its right-hand side, of a Newton
    /// system whose solve stopped short (solve_linearized()) that still
    /// gives a step.
    constexpr double inexact_step_reduction = 0.1;

    /**
     * One linear problem of the method: moves du onto the node conditions
     * (du = du_D + w) and solves for w in the subspace where they are
     * homogeneous, until the residual is @p reduction times the initial one
     * or times @p residual_scale, the size of the nonlinear residual at the
     * iterate, if that is smaller (not below @p floor); then du += w.
     * Returns the linear iterations; throws SolverControl::NoConvergence
     * where the solve stopped short above inexact_step_reduction of the
     * right-hand side.
     *
     * Inexact Newton asks |F + J s| <= eta |F| of the linearised residual,
     * relative to the residual F at the iterate; the right-hand side here
     * is the residual after the node conditions moved du, which is far
     * larger where moving the contact nodes loads a stiff body (a slave
     * side much stiffer than its master): solved to eta times it, the step
     * left force errors above the contact forces themselves, and the line
     * search cut every step to its shortest (doc/algorithm.md, "Bodies of
     * very different stiffness").
     */
    template <int dim>
    unsigned int
    solve_linearized(const IncrementalProblem<dim>      &problem,
                     const ActiveSets<dim>              &sets,
                     const NodeProjection<dim>          &P,
                     const ConditionPreconditioner<dim> &preconditioner,
                     ShiftedStiffnessSolver             &linear_solver,
                     const bool                          friction,
                     const std::vector<Tensor<1, dim>>  &r,
                     const double                        reduction,
                     const double                        residual_scale,
                     const double                        floor,
                     TrilinosWrappers::MPI::Vector      &du,
                     TrilinosWrappers::MPI::Vector      &K_du,
                     TrilinosWrappers::MPI::Vector      &rhs,
                     TrilinosWrappers::MPI::Vector      &w)
    {
      const StiffnessOperator &K = problem.stiffness;
      const MPI_Comm           comm = du.get_mpi_communicator();
      double                   moved = 0;
      if (problem.nonlinear != nullptr)
        w = du; // the iterate before the move, for the linearisation below
      const bool any_slip = Utilities::MPI::logical_or(
        impose_node_conditions(problem, sets.conditions, du, moved) && friction,
        comm);
      const ContactStiffness<dim> A(K,
                                    P,
                                    problem.contact,
                                    sets.conditions,
                                    sets.slip_direction,
                                    sets.robin,
                                    any_slip,
                                    problem.contact_held.stabilization,
                                    problem.contact.frames_follow_configuration() ?
                                      &r :
                                      nullptr);
      // K du at du_D. A nonlinear law's N(du) and tangent were made at the
      // iterate (search_along_step()); where the node conditions moved it,
      // N(du) linearised there, N(du_0) + K_T (du - du_0): the step of
      // Newton's method with the node conditions as constraints of the
      // linearisation, without another evaluation of the law (which could
      // also invert a cell: the contact nodes moved, the cells behind them
      // not yet).
      if (problem.nonlinear == nullptr)
        problem.internal_force(du, K_du);
      else if (Utilities::MPI::max(moved, comm) >
               1e-14 * std::max(problem.length_scale, du.linfty_norm()))
        {
          w.sadd(-1., 1., du);
          K.vmult(rhs, w);
          K_du += rhs;
        }
      rhs = problem.load;
      rhs -= K_du;
      if (any_slip)
        add_slip_terms(problem, A, sets, du, rhs);
      P.apply(rhs);

      w = 0;
      const Timer  timer;
      unsigned int iterations = 0;
      try
        {
          iterations = solve_newton_system(
            A,
            ProjectedPreconditioner<dim, ConditionPreconditioner<dim>>(
              preconditioner, P),
            linear_solver.volumetric_split(),
            linear_solver.preconditioner_varies(),
            any_slip || !K.is_symmetric() || !problem.gap_slopes.empty(),
            K.is_assembled() ? 30 : 12,
            linear_solver.maximum_iterations(),
            std::max(reduction * std::min(rhs.l2_norm(), residual_scale), floor),
            rhs,
            w);
        }
      catch (const SolverControl::NoConvergence &e)
        {
          // A solve that stopped short but reduced its residual to
          // inexact_step_reduction of the right-hand side still gives an
          // inexact Newton step, which the line search judges; a worse
          // one fails the Newton iteration.
          if (!(e.last_residual <= inexact_step_reduction * rhs.l2_norm()))
            {
              linear_solver.krylov_seconds += timer.wall_time();
              throw;
            }
          iterations = e.last_step;
        }
      linear_solver.krylov_seconds += timer.wall_time();
      du += w;
      return iterations;
    }



    /// The residuals at (du, r) with r projected onto the cones (into
    /// @p admissible_r); @p T_r and @p scratch are work vectors.
    template <int dim>
    Residuals
    admissible_residuals(const IncrementalProblem<dim>       &problem,
                         const TrilinosWrappers::MPI::Vector &du,
                         const TrilinosWrappers::MPI::Vector &K_du,
                         const std::vector<Tensor<1, dim>>   &r,
                         std::vector<Tensor<1, dim>>         &admissible_r,
                         TrilinosWrappers::MPI::Vector       &T_r,
                         TrilinosWrappers::MPI::Vector       &scratch)
    {
      for (unsigned int j = 0; j < r.size(); ++j)
        admissible_r[j] = problem.contact.friction_cone(j).project(r[j]);
      problem.contact.apply(admissible_r, T_r);
      return compute_residuals(problem, du, K_du, T_r, admissible_r, scratch);
    }



    /**
     * The stopping rule: force balance below tolerance F, penetration
     * below tolerance L, complementarity below tolerance F L, with F the
     * largest of |p|, |K du| (a moving obstacle or tool may drive the
     * body without any load) and, for a nonlinear law, |f_int(u)| (an
     * increment's load is a small part of the forces in the body), and L
     * the larger of the length scale and max |du|.
     */
    template <int dim>
    bool
    meets(const double                         tolerance,
          const IncrementalProblem<dim>       &problem,
          const TrilinosWrappers::MPI::Vector &du,
          const TrilinosWrappers::MPI::Vector &K_du,
          const Residuals                     &res)
    {
      const double force =
        std::max({problem.load.l2_norm(),
                  K_du.l2_norm(),
                  problem.nonlinear != nullptr ? problem.nonlinear->force_scale() : 0.});
      const double length = std::max(problem.length_scale, du.linfty_norm());
      return res.force_balance <= tolerance * force &&
             res.penetration <= tolerance * length &&
             res.complementarity <= tolerance * force * length;
    }

    /// (du, r) = (1 - t) (previous_du, previous_r) + t (du, r).
    template <int dim>
    void
    shorten_step(const double                         t,
                 const TrilinosWrappers::MPI::Vector &previous_du,
                 const std::vector<Tensor<1, dim>>   &previous_r,
                 TrilinosWrappers::MPI::Vector       &du,
                 std::vector<Tensor<1, dim>>         &r)
    {
      du.sadd(t, 1 - t, previous_du);
      for (unsigned int j = 0; j < r.size(); ++j)
        r[j] = (1 - t) * previous_r[j] + t * r[j];
    }

    /**
     * The vectors of one solve besides (du, r): K du and T r of the
     * current iterate, the previous iterate that the line search goes back
     * along, and work vectors.
     */
    template <int dim>
    struct NewtonWorkspace
    {
      NewtonWorkspace(const TrilinosWrappers::MPI::Vector &du,
                      const unsigned int                   n_candidates)
        : K_du(du)
        , rhs(du)
        , w(du)
        , T_r(du)
        , scratch(du)
        , previous_du(du)
        , previous_residual(du)
        , residual(du)
        , previous_r(n_candidates)
        , admissible_r(n_candidates)
      {}

      TrilinosWrappers::MPI::Vector K_du, rhs, w, T_r, scratch, previous_du;
      /// T r of the previous iterate (kept for nonlinear laws only, whose
      /// line search evaluates the force balance along the step).
      TrilinosWrappers::MPI::Vector previous_T_r;
      /// The force balance residuals K du - p - T r of both iterates.
      TrilinosWrappers::MPI::Vector previous_residual, residual;
      std::vector<Tensor<1, dim>>   previous_r, admissible_r;
      /// What the last step shortened because it inverted a cell met
      /// (InvertedCell's line; empty: none), for a stall's failure line.
      std::string inverted_cell;
    };



    /// Keeps (du, r) and their force balance residual as the previous
    /// iterate.
    template <int dim>
    void
    remember_iterate(const IncrementalProblem<dim>       &problem,
                     const TrilinosWrappers::MPI::Vector &du,
                     const std::vector<Tensor<1, dim>>   &r,
                     NewtonWorkspace<dim>                &work)
    {
      work.previous_du       = du;
      work.previous_r        = r;
      if (problem.nonlinear != nullptr)
        work.previous_T_r = work.T_r;
      work.previous_residual = work.K_du;
      work.previous_residual -= problem.load;
      work.previous_residual -= work.T_r;
    }



    /// How often a Newton step that inverts a cell is halved before the
    /// solve stops (2^-20: the step has vanished).
    constexpr unsigned int max_halvings_for_inverted_cells = 20;

    /**
     * After the linear solve: the reactions of the new du, then the line
     * search along the segment from the previous iterate, on the
     * complementarity functions and the force balance (a full step can
     * make the stick/slip sets cycle, a shorter one cannot increase this
     * merit; the force balance is linear along the segment). Leaves (du,
     * r), K du and T r at the accepted point.
     */
    template <int dim>
    LineSearchStep
    search_along_step(const IncrementalProblem<dim>    &problem,
                      const std::vector<NodeCondition> &conditions,
                      const std::vector<double>        &c,
                      const std::vector<double>        &c_t,
                      const bool                        friction,
                      const double                      mean_c,
                      const TrilinosWrappers::MPI::Vector &balance_weight,
                      TrilinosWrappers::MPI::Vector    &du,
                      std::vector<Tensor<1, dim>>      &r,
                      NewtonWorkspace<dim>             &work,
                      const bool                        tangent_at_step)
    {
      // With a nonlinear law, also its tangent here for the next step
      // (unless @p tangent_at_step is false: a step that is likely the
      // last); a step that inverts a cell (finite strain) is halved until
      // it does not.
      for (unsigned int halvings = 0;; ++halvings)
        try
          {
            problem.internal_force(du, work.K_du, tangent_at_step);
            break;
          }
        catch (const InvertedCell &e)
          {
            if (halvings == max_halvings_for_inverted_cells)
              throw;
            work.inverted_cell = e.what();
            shorten_step(0.5, work.previous_du, work.previous_r, du, r);
          }
      work.scratch = work.K_du;
      work.scratch -= problem.load;
      active_reactions(problem.contact, conditions, work.scratch, r);
      problem.contact.apply(r, work.T_r);
      work.residual = work.K_du;
      work.residual -= problem.load;
      work.residual -= work.T_r;
      // A nonlinear law's residual along the step, by evaluating it (w and
      // rhs are free once the step is taken).
      std::function<const TrilinosWrappers::MPI::Vector *(double)> nonlinear_residual;
      if (problem.nonlinear != nullptr)
        nonlinear_residual = [&](const double t) -> const TrilinosWrappers::MPI::Vector * {
          work.w = work.previous_du;
          work.w.sadd(1 - t, t, du);
          try
            {
              problem.internal_force(work.w, work.rhs);
            }
          catch (const InvertedCell &e)
            {
              work.inverted_cell = e.what();
              return nullptr;
            }
          work.rhs -= problem.load;
          work.rhs.add(-(1 - t), work.previous_T_r, -t, work.T_r);
          return &work.rhs;
        };
      const MeritAlongStep<dim> merit(problem, conditions, c, c_t, friction, mean_c, balance_weight,
                                      work.previous_du, du, work.previous_r, r,
                                      work.previous_residual, work.residual,
                                      work.scratch, nonlinear_residual);
      const LineSearchStep step = line_search(merit);
      if (step.t < 1)
        {
          shorten_step(step.t, work.previous_du, work.previous_r, du, r);
          problem.internal_force(du, work.K_du, /*with_tangent=*/true);
          problem.contact.apply(r, work.T_r);
        }
      return step;
    }

    /**
     * Whether the Newton step from the current iterate (residuals @p now,
     * the force balance @p force_balance_before at the iterate before it)
     * will likely meet the tolerance, so that the line search need not
     * take a nonlinear law's tangent at its end (at finite strain the
     * tangent more than doubles the cost of the cells' pass): no node
     * changed its condition, the force balance contracts, and after the step,
     * predicted as quadratic convergence (the last contraction squared)
     * or the forcing term's reduction, whichever is larger, it is a half
     * of what meets() asks, while the other residuals already are. A
     * wrong guess costs a force pass: the tangent is then taken at the
     * next iteration, at the same iterate.
     */
    template <int dim>
    bool
    likely_last_step(const double                         tolerance,
                     const IncrementalProblem<dim>       &problem,
                     const TrilinosWrappers::MPI::Vector &du,
                     const TrilinosWrappers::MPI::Vector &K_du,
                     const Residuals                     &now,
                     const double                         force_balance_before,
                     const double                         forcing_term,
                     const unsigned int                   changes)
    {
      if (problem.nonlinear == nullptr || changes > 0 || !(force_balance_before > 0))
        return false;
      const double contraction = now.force_balance / force_balance_before;
      if (!(contraction < 0.5))
        return false;
      Residuals after = now;
      after.force_balance =
        now.force_balance * std::max(contraction * contraction, forcing_term);
      return meets(0.5 * tolerance, problem, du, K_du, after);
    }

    /// Newton steps without progress after which the forcing term falls
    /// back to the fixed rule (ForcingTerm::fall_back()), and after which
    /// steps that were all shortened where they would invert a cell stop
    /// the solve.
    constexpr unsigned int steps_before_fall_back = 5;

    /// Why the linear solve of Newton iteration @p k failed, and the fix.
    inline std::string
    linear_failure(const unsigned int                   k,
                   const SolverControl::NoConvergence &e,
                   const unsigned int                   max_iterations)
    {
      const std::string what =
        "the linear solve of Newton iteration " + std::to_string(k + 1) +
        " did not converge (residual " + Input::scientific(e.last_residual) +
        " after " + std::to_string(e.last_step) + " iterations";
      if (e.last_step >= max_iterations)
        return what + "); raise <Linear solver/Maximum iterations>";
      return what + ", stagnating: it fell by less than a tenth in the "
                    "last " + std::to_string(StagnationControl::window) +
             "); try smaller increments (Loading/On failure = cut increment)";
    }

    /// Why the iterations from @p first to @p k made no progress; with
    /// @p inverted_cell (InvertedCell's line) if the last step was
    /// shortened because it inverted a cell.
    inline std::string
    stall_failure(const unsigned int first,
                  const unsigned int k,
                  const std::string &inverted_cell)
    {
      const std::string what = "no progress from Newton iteration " +
                               std::to_string(first + 1) + " to " +
                               std::to_string(k + 1);
      if (!inverted_cell.empty())
        return what + ": the steps are blocked where they would invert a "
                      "cell, " + inverted_cell;
      return what + " (the merit did not fall by a tenth in 25 steps: the "
                    "stick/slip sets keep changing, or the residuals are at "
                    "round-off and Tolerance is below it); try smaller "
                    "increments, Loading/On failure = cut increment, or "
                    "Method = accelerated primal-dual";
    }
  } // namespace SemismoothNewton
} // namespace FrictionalContact
