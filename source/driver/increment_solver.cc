#include <deal.II/base/mpi.h>

#include <frictional_contact/base/input.h>
#include <frictional_contact/driver/contact_geometry_at_iterates.h>
#include <frictional_contact/driver/increment_response.h>
#include <frictional_contact/driver/increment_solver.h>

namespace FrictionalContact
{
  template <int dim>
  void
  IncrementSolver<dim>::declare_parameters(ParameterHandler &prm)
  {
    ContactSolverParameters<dim>::declare_parameters(prm);
    ShiftedStiffnessSolver::declare_parameters(prm);
  }



  template <int dim>
  IncrementSolver<dim>::IncrementSolver(ParameterHandler         &prm,
                                        const ConditionalOStream &pcout)
    : pcout(pcout)
    , linear_solver(prm, dim)
    , solver(prm, pcout)
  {}



  template <int dim>
  std::unique_ptr<IncrementalProblem<dim>>
  IncrementSolver<dim>::make_problem(
    const Model<dim>                    &model,
    const TrilinosWrappers::MPI::Vector &load,
    const TrilinosWrappers::MPI::Vector &start,
    const Tensor<1, dim>                &obstacle_motion) const
  {
    const ContactOperator<dim> &contact = model.get_contact();
    auto problem = std::make_unique<IncrementalProblem<dim>>(
      stiffness(model), load, contact);
    problem->largest_singular_value_T = sigma_T;
    for (unsigned int j = 0; j < contact.n_local(); ++j)
      {
        // Small deformations: g_j^{l+1} = g_j^0(obstacle at t) - t_n,j^T u^l
        // (with the prescribed part of the increment).
        problem->gaps.push_back(contact.gap_at_start(j, start));
        problem->obstacle_slip.push_back(contact.prescribed_slip(j, obstacle_motion));
      }
    describe_contact_held_bodies(model, problem->contact_held);
    return problem;
  }



  template <int dim>
  void
  IncrementSolver<dim>::describe_contact_held_bodies(
    const Model<dim>   &model,
    ContactHeldBodies &held) const
  {
    const std::set<types::material_id> &ids = model.bodies_held_by_contact_alone();
    if (ids.empty())
      return;
    const ElasticBody<dim>     &body    = model.get_body();
    const ContactOperator<dim> &contact = model.get_contact();
    std::map<types::material_id, unsigned int> bit;
    for (const types::material_id id : ids)
      {
        bit[id] = held.names.size();
        held.names.push_back(body.body_name(id));
      }
    for (unsigned int j = 0; j < contact.n_local(); ++j)
      {
        std::uint64_t bits = 0;
        for (const types::material_id id : contact.bodies_held_by(j))
          if (const auto it = bit.find(id); it != bit.end())
            bits |= std::uint64_t(1) << it->second;
        held.held_by_candidate.push_back(bits);
      }
    const StiffnessOperator &K         = stiffness(model);
    const std::vector<bool>  of_bodies = body.owned_dofs_of(ids);
    held.stabilization                 = body.make_vector();
    const IndexSet &owned              = body.locally_owned_dofs();
    double         *S                  = held.stabilization.begin();
    for (unsigned int i = 0; i < of_bodies.size(); ++i)
      if (of_bodies[i])
        S[i] = ContactHeldBodies::stabilization_factor *
               std::abs(K.diag_element(owned.nth_index_in_set(i)));
  }



  template <int dim>
  bool
  IncrementSolver<dim>::elastic_trial() const
  {
    return solver.try_elastic_first && solver.method->wants_elastic_trial();
  }



  template <int dim>
  void
  IncrementSolver<dim>::start_increment(Model<dim>                          &model,
                                        const TrilinosWrappers::MPI::Vector &start,
                                        const TrilinosWrappers::MPI::Vector &lifting,
                                        const double                         load_factor,
                                        IncrementOutcome<dim>               &outcome,
                                        TimerOutput                         &timer)
  {
    // Timed alike for every law: small strain's p - K u_0 and pairs' basis
    // are as much the increment's cost as a nonlinear law's tangent.
    TimerOutput::Scope             scope(timer, "Increment start");
    const ElasticBody<dim>        &body    = model.get_body();
    const ContactOperator<dim>    &contact = model.get_contact();
    TrilinosWrappers::MPI::Vector &load    = *outcome.load;
    if (contact.has_pairs())
      {
        // The contact pairs were updated to this configuration: the basis
        // in which their conditions are node-local, K_w and its AMG.
        if (geometric)
          {
            linear_solver.set_geometric_multigrid(nullptr, nullptr);
            mortar_cycle.reset();
          }
        // K_w of K as it is is what the first preconditioners on this mesh
        // are built from and what linear laws solve with; a nonlinear
        // law's solves take the tangent at the start, made below.
        mortar = std::make_shared<MortarBasis<dim>>(
          body, contact, !model.nonlinear() || !preconditioner_basis);
      }
    // p - f_int(u_0): for linear laws p - K u_0; nonlinear ones evaluate
    // f_int(u_0) and the tangent there.
    if (model.nonlinear())
      {
        // The first Newton step is linearised at u^l (the moved boundary
        // alone squashes the cells beside it, and flows them).
        outcome.response =
          std::make_unique<IncrementResponse<dim>>(model, mortar.get(), start, lifting);
        load = outcome.response->start_force();
      }
    else
      body.internal_force(start, load);
    load.sadd(-1., load_factor, body.load_vector());
    const bool rebuild = rebuild_for_tangent && !geometric;
    rebuild_for_tangent = false;
    if (rebuild)
      krylov_per_step_after_build = 0;
    if (rebuild && !contact.has_pairs())
      {
        // The tangent at the start is in K's matrix itself.
        linear_solver.release();
        initialize_on_body(body);
      }
    if (contact.has_pairs())
      {
        prepare_mortar_solves(body, rebuild);
        mu_pi = 0;
        const TrilinosWrappers::MPI::Vector load_in_u = load;
        mortar->force_to_w(load_in_u, load);
      }
  }



  template <int dim>
  IncrementOutcome<dim>
  IncrementSolver<dim>::solve(Model<dim>        &model,
                              const State<dim>  &state,
                              const unsigned int increment,
                              const double      t_start,
                              const double      t_end,
                              const double      load_factor_start,
                              const double      load_factor,
                              const bool        record_history,
                              TimerOutput      &timer,
                              const WarmStart<dim> *warm_start)
  {
    const ElasticBody<dim>     &body    = model.get_body();
    const ContactOperator<dim> &contact = model.get_contact();

    // The increment of the prescribed displacements, and the configuration
    // it leads to before the rest of the increment is solved for.
    TrilinosWrappers::MPI::Vector lifting = body.make_vector();
    body.prescribed_increment(t_start, t_end, lifting);
    Input::require_finite(lifting.l2_norm(),
                          "Boundary conditions/Prescribed displacement",
                          t_end);
    TrilinosWrappers::MPI::Vector start = state.u;
    start += lifting;
    const IncrementDrive<dim> drive =
      solver.start_from_last_increment ?
        IncrementDrive<dim>(lifting,
                            IncrementDrive<dim>::rigid_parts_of(load_factor - load_factor_start,
                                                                contact, t_start, t_end)) :
        IncrementDrive<dim>();
    const double motion_scale =
      warm_start ? 0. : last_motion_scale(drive, t_end - t_start);
    if (!warm_start)
      started_from_last_motion = motion_scale > 0;
    if (contact.follows_configuration())
      model.get_contact().follow_configuration(start);

    IncrementOutcome<dim> outcome;
    outcome.load = std::make_unique<TrilinosWrappers::MPI::Vector>(
      body.make_vector());
    TrilinosWrappers::MPI::Vector &load = *outcome.load;
    start_increment(model, start, lifting, load_factor, outcome, timer);

    outcome.du_solved       = body.make_vector();
    SolveStatistics &result = outcome.statistics;
    // Without contact, a linear body's increment is one elastic solve; a
    // nonlinear one's takes Newton's method like a contact problem.
    const bool newton_without_contact = !contact.active() && model.nonlinear();
    if ((!contact.active() && !model.nonlinear()) || elastic_trial())
      {
        TimerOutput::Scope scope(timer, "Elastic solve");
        const Timer        wall;
        const unsigned int setups_before = linear_solver.n_amg_setups;
        result.linear_iterations =
          linear_solver.solve(0.,
                              outcome.du_solved,
                              load,
                              linear_solver.relative_tolerance() *
                                load.l2_norm());
        result.amg_setups = linear_solver.n_amg_setups - setups_before;
        result.seconds    = wall.wall_time();
        if (!std::isfinite(outcome.du_solved.l2_norm()))
          throw SolverError("increment " + std::to_string(increment) +
                            " (t = " + Input::to_text(t_end) + ")" +
                            ": the elastic solve gave a displacement that is "
                            "not finite");
      }
    if (contact.active() || newton_without_contact)
      {
        const Tensor<1, dim> obstacle_motion =
          contact.obstacle_displacement(t_end) - contact.obstacle_displacement(t_start);
        outcome.problem = make_problem(model, load, start, obstacle_motion);
        outcome.problem->nonlinear = outcome.response.get();
        if (warm_start)
          outcome.problem->tolerance = warm_start->tolerance;
        std::unique_ptr<ContactGeometryAtIterates<dim>> geometry;
        if (contact.geometry_follows_iterates())
          geometry = std::make_unique<ContactGeometryAtIterates<dim>>(
            model.get_contact(), *outcome.problem, body, mortar.get(), load, start,
            t_start, t_end, obstacle_motion);
        outcome.problem->geometry = geometry.get();
        solve_contact(model, state, start, motion_scale, outcome, record_history,
                      timer, warm_start);
        outcome.problem->geometry = nullptr;
        if (!result.converged)
          return outcome;
        if (contact.active())
          outcome.results = contact_results(contact, state, outcome);
      }
    else
      {
        result.iterations = 1;
        result.converged  = true;
      }
    if (model.nonlinear())
      note_krylov_growth(result);
    outcome.du = outcome.du_solved;
    if (mortar)
      mortar->displacement_to_u(outcome.du_solved, outcome.du);
    body.get_constraints().distribute(outcome.du);
    if (solver.start_from_last_increment)
      {
        last_motion = outcome.du;
        last_length = t_end - t_start;
        last_drive  = drive;
      }
    outcome.du += lifting;
    return outcome;
  }



  template <int dim>
  double
  IncrementSolver<dim>::basis_change_in_preconditioner(const ElasticBody<dim> &body) const
  {
    // x: a fixed field of every dof (the same on any rank count), zero at
    // the held ones.
    TrilinosWrappers::MPI::Vector x = body.make_vector(), change = x, mapped = x;
    for (const types::global_dof_index i : x.locally_owned_elements())
      x[i] = std::sin(1. + 0.618 * i);
    x.compress(VectorOperation::insert);
    body.get_constraints().set_zero(x);
    // (K_w - K_w,old) x, and what the preconditioner makes of it.
    mortar->stiffness().vmult(change, x);
    preconditioner_matrix->vmult(mapped, x);
    change -= mapped;
    linear_solver.precondition_stiffness(mapped, change);
    const double relative = mapped.l2_norm() / x.l2_norm();
    return relative;
  }



  template <int dim>
  void
  IncrementSolver<dim>::prepare_mortar_solves(const ElasticBody<dim> &body,
                                              bool                    rebuild)
  {
    // Built again on K_w as it is (a copy) where the basis moved far
    // from the one the AMG was built in (the geometric multigrid's cycle
    // is made with each new basis below).
    if (preconditioner_basis && !rebuild && !geometric &&
        basis_change_in_preconditioner(body) > largest_basis_change)
      rebuild = true;
    if (preconditioner_basis && !rebuild)
      // The AMG of an earlier increment on this mesh still serves: the
      // mortar rows changed little since (doc/performance.md, "Two
      // bodies").
      linear_solver.replace_matrix(mortar->stiffness(),
                                   mortar->volumetric_split());
    else
      {
        // The preconditioners from K_w as the basis was made (for a
        // nonlinear law the solves then take its tangent).
        linear_solver.release();
        // On a copy of the tangent K_T,w at the start when rebuilt for
        // it (the basis makes K_T,w anew at each Newton step).
        if (rebuild)
          {
            // Emptied first: copy_from() into a matrix of another
            // pattern decides per rank whether to copy the layout, and
            // ranks that decide differently wait for each other forever.
            tangent_copy.clear();
            tangent_copy.copy_from(mortar->stiffness().matrix("the preconditioner"));
            tangent_copy_operator = std::make_unique<AssembledStiffness>(tangent_copy);
          }
        preconditioner_matrix =
          rebuild ? tangent_copy_operator.get() : &mortar->initial_stiffness();
        linear_solver.initialize(*preconditioner_matrix,
                                 mortar->modes_to_w(body.rigid_body_modes()),
                                 0.,
                                 mortar->volumetric_split());
        linear_solver.replace_matrix(mortar->stiffness(),
                                     mortar->volumetric_split());
        preconditioner_basis = mortar;
      }
    if (geometric)
      {
        // One cycle of K for K_w and for the Newton systems.
        mortar_cycle =
          std::make_unique<MortarPreconditioner<dim>>(*geometric, *mortar);
        linear_solver.set_geometric_multigrid(mortar_cycle.get(),
                                              mortar_cycle.get());
      }
  }



  template <int dim>
  void
  IncrementSolver<dim>::solve_contact(const Model<dim>      &model,
                                      const State<dim>      &state,
                                      const TrilinosWrappers::MPI::Vector &start,
                                      const double           motion_scale,
                                      IncrementOutcome<dim> &outcome,
                                      const bool             record_history,
                                      TimerOutput           &timer,
                                      const WarmStart<dim>  *warm_start)
  {
    const ContactOperator<dim>    &contact = model.get_contact();
    const MPI_Comm                 comm    = model.get_mpi_communicator();
    IncrementalProblem<dim>       &problem = *outcome.problem;
    TrilinosWrappers::MPI::Vector &du      = outcome.du_solved;
    SolveStatistics               &result  = outcome.statistics;
    std::vector<Tensor<1, dim>>   &r       = outcome.reactions;
    r.assign(contact.n_local(), Tensor<1, dim>());

    // A length for tolerances that follow the units: the largest gap,
    // displacement so far, or elastic displacement of this increment.
    double largest_gap = 0;
    for (const double g : problem.gaps)
      largest_gap = std::max(largest_gap, std::abs(g));
    // Without the elastic trial, the Newton method measures with its own
    // displacement (meets(): the larger of this and max |du|).
    problem.length_scale =
      std::max({Utilities::MPI::max(largest_gap, comm),
                start.linfty_norm(),
                elastic_trial() ? du.linfty_norm() : 0.});
    if (!(problem.length_scale > 0) && solver.method->wants_elastic_trial())
      problem.length_scale = 1;

    bool separates = false;
    if (elastic_trial())
      {
        bool penetrates = false;
        for (unsigned int j = 0; j < contact.n_local() && !penetrates; ++j)
          penetrates = problem.gap_at(j, problem.relative_displacement(j, du)) < 0;
        separates = !Utilities::MPI::logical_or(penetrates, comm);
      }
    if (separates)
      {
        // Every node free, r = 0: only the residuals are left to compute.
        const ElasticBody<dim>       &body     = model.get_body();
        TrilinosWrappers::MPI::Vector K_du     = body.make_vector();
        TrilinosWrappers::MPI::Vector no_force = body.make_vector();
        TrilinosWrappers::MPI::Vector scratch  = body.make_vector();
        stiffness(model).vmult(K_du, du);
        result.residuals =
          compute_residuals(problem, du, K_du, no_force, r, scratch);
        result.converged = true;
        return;
      }

    // Warm start: the reactions of the previous increment, and du = 0 or
    // the previous increment's motion scaled to this one; or the
    // reactions of another solve of this increment, and its du.
    const std::vector<Tensor<1, dim>> &forces =
      warm_start ? warm_start->forces : state.contact_forces;
    for (unsigned int j = 0; j < contact.n_local(); ++j)
      r[j] = contact.friction_cone(j).project(contact.to_local(j, forces[j]));
    du = 0;
    if (warm_start || motion_scale > 0)
      {
        TrilinosWrappers::MPI::Vector motion =
          warm_start ? warm_start->du : last_motion;
        if (!warm_start)
          motion *= motion_scale;
        if (mortar)
          mortar->displacement_to_w(motion, du);
        else
          du = motion;
        model.get_body().get_constraints().set_zero(du);
      }
    if (solver.method->needs_smallest_eigenvalue())
      problem.smallest_eigenvalue_K = smallest_eigenvalue_of_K(model, timer);
    if (mortar)
      problem.master_stiffness = mortar->master_stiffness(model.get_body(), contact);
    const SolveStatistics elastic = result;
    {
      TimerOutput::Scope scope(timer, "Contact solve");
      result = solver.method->solve(problem, linear_solver, du, r, record_history);
    }
    if (!result.converged)
      result.worst_places = worst_places(problem, du);
    result.linear_iterations += elastic.linear_iterations;
    result.amg_setups += elastic.amg_setups;
    result.seconds += elastic.seconds;
  }



  template <int dim>
  void
  IncrementSolver<dim>::note_krylov_growth(const SolveStatistics &result)
  {
    if (result.iterations == 0)
      return;
    const double per_step = double(result.linear_iterations) / result.iterations;
    if (krylov_per_step_after_build == 0)
      krylov_per_step_after_build = per_step;
    else
      rebuild_for_tangent = linear_solver.tangent_rebuild_factor() > 0 &&
                            per_step > linear_solver.tangent_rebuild_factor() *
                                         krylov_per_step_after_build;
  }



  template <int dim>
  ContactResults<dim>
  IncrementSolver<dim>::contact_results(const ContactOperator<dim>  &contact,
                                        const State<dim>            &state,
                                        const IncrementOutcome<dim> &outcome) const
  {
    const IncrementalProblem<dim>     &problem = *outcome.problem;
    const std::vector<Tensor<1, dim>> &r       = outcome.reactions;
    ContactResults<dim>                results;
    results.reaction = r;
    for (unsigned int j = 0; j < contact.n_local(); ++j)
      {
        results.reaction_increment.push_back(
          r[j] - contact.to_local(j, state.contact_forces[j]));
        results.local_displacement.push_back(
          problem.relative_displacement(j, outcome.du_solved));
        results.gap.push_back(problem.gap_at(j, results.local_displacement.back()));
        results.state.push_back(contact.friction_cone(j).state(r[j]));
        const double area = contact.nodal_area(j);
        results.pressure.push_back(area > 0 ? -r[j][0] / area : 0.);
      }
    return results;
  }

  template class IncrementSolver<2>;
  template class IncrementSolver<3>;
} // namespace FrictionalContact
