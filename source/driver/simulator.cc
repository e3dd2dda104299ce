#include <deal.II/base/utilities.h>

#include <frictional_contact/base/files.h>
#include <frictional_contact/driver/simulator.h>
#include <frictional_contact/postprocess/screen_report.h>

#include <boost/archive/text_iarchive.hpp>
#include <boost/archive/text_oarchive.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>

#include <sstream>

namespace FrictionalContact
{
  template <int dim>
  void
  Simulator<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Dimension",
                      "2",
                      Patterns::Integer(2, 3),
                      "Space dimension of the scene: 2 or 3.");
    prm.declare_entry("Output directory",
                      "output",
                      Patterns::DirectoryName(),
                      "Where results are written (created if needed).");
    prm.declare_entry("Resume computation",
                      "false",
                      Patterns::Selection("false|true|auto"),
                      "true: continue the loading history from the checkpoint "
                      "in the output directory (written after each increment, "
                      "see Output/Checkpoint every), for example after the "
                      "run was killed; the number of MPI ranks may differ. "
                      "auto: resume if there is a checkpoint, else start.");
    Model<dim>::declare_parameters(prm);
    AdaptiveRefinement<dim>::declare_parameters(prm);
    IncrementDriver::declare_parameters(prm);
    IncrementSolver<dim>::declare_parameters(prm);
    Postprocess::Manager<dim>::declare_parameters(prm);
  }



  namespace
  {
    /// The parameters as read: before the Model, whose automatic choices
    /// (Model::choose_matrix_free_for_memory()) may set entries that a
    /// resumed run, on the memory it then has, decides again.
    std::string
    printed(const ParameterHandler &prm)
    {
      std::ostringstream parameters;
      prm.print_parameters(parameters, ParameterHandler::ShortPRM);
      return parameters.str();
    }
  } // namespace



  template <int dim>
  Simulator<dim>::Simulator(ParameterHandler &prm, const MPI_Comm comm)
    : mpi_communicator(comm)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
    , output_directory(prm.get("Output directory"))
    , parameters_as_run(printed(prm))
    , model(prm, comm)
    , adaptivity(prm)
    , driver(prm)
    , increment_solver(prm, pcout)
    , postprocessors(prm, output_directory, comm)
    , checkpoint(output_directory, comm)
  {
    const std::string resume_choice = prm.get("Resume computation");
    resume_if_possible = resume_choice == "auto";
    resume             = resume_choice == "true" ||
             (resume_if_possible && checkpoint.exists());
    postprocessors.check_scene(driver.times().size(), model);
  }



  template <int dim>
  void
  Simulator<dim>::setup()
  {
    // Made here, not in the constructor, so that a parameter error there
    // does not meet a TimerOutput that complains about it.
    timer = std::make_unique<TimerOutput>(mpi_communicator,
                                          pcout,
                                          TimerOutput::never,
                                          TimerOutput::wall_times);
    {
      TimerOutput::Scope scope(*timer, "Setup");
      if (resume)
        {
          {
            // The defaults of this program, for entries a checkpoint of an
            // older one lacks.
            ParameterHandler defaults;
            declare_parameters(defaults);
            checkpoint.verify(parameters_as_run, printed(defaults));
          }
          model.setup([&](auto &mesh) { checkpoint.load_mesh(mesh); });
        }
      else
        model.setup();
    }
    {
      TimerOutput::Scope scope(*timer, "Assembly");
      model.assemble();
    }

    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
    pcout << "-- contact " << FRICTIONAL_CONTACT_VERSION << " on deal.II "
          << DEAL_II_PACKAGE_VERSION << ", " << n_ranks << " MPI rank"
          << (n_ranks > 1 ? "s" : "") << std::endl;
    model.print_summary(pcout);
    if (adaptivity.active())
      pcout << "Mesh refinement: " << adaptivity.describe() << std::endl;
    pcout << "Loading: " << driver.loading().describe() << std::endl;
    for (const std::string &note : driver.loading().overridden_entries())
      pcout << "Note: " << note << std::endl;
    const std::string written =
      postprocessors.describe(driver.times().size());
    pcout << "Output: "
          << (written.empty() ? "nothing" :
                                written + " in " + output_directory + "/")
          << std::endl;
  }



  template <int dim>
  void
  Simulator<dim>::run()
  {
    const unsigned int n_initial = driver.times().size();
    // The folder is checked and locked before anything in it is read or
    // written (a resume repairs a checkpoint caught between renames).
    if (resume || postprocessors.writes_files() ||
        postprocessors.checkpoint_due(n_initial, n_initial))
      {
        check_output_directory(output_directory, mpi_communicator);
        lock.emplace(output_directory, mpi_communicator);
      }
    setup();
    state.u = model.get_body().make_vector();
    state.contact_forces.assign(model.get_contact().n_local(), Tensor<1, dim>());
    const unsigned int first_increment = resume ? load_checkpoint() : 0;
    if (first_increment == driver.times().size())
      {
        pcout << "Resume computation = auto: the loading history is complete "
                 "(increment "
              << first_increment << " of " << first_increment << " in "
              << checkpoint.path() << "): nothing to do" << std::endl;
        return;
      }
    increment_solver.initialize(model);
    increment_solver.print_method();
    solve_increments(first_increment);
    timer->print_wall_time_statistics(mpi_communicator);
    print_summary();
  }



  template <int dim>
  void
  Simulator<dim>::solve_increments(const unsigned int first_increment)
  {
    n_finished      = first_increment;
    last_checkpoint = first_increment;
    // The driver's lines (cuts, growth) once, from the first rank: a
    // stream without a buffer writes nothing.
    std::ostream nowhere(nullptr);
    try
      {
        driver.run(
          first_increment,
          [&](const unsigned int l) { return solve_increment(l); },
          [&](const unsigned int l) { finish_increment(l); },
          pcout.is_active() ? pcout.get_stream() : nowhere);
      }
    catch (const StopRequested &stop)
      {
        stop_on_signal(stop.signal);
      }
    catch (const WriteError &error)
      {
        throw WriteError(std::string(error.what()) + "; " + what_is_left());
      }
  }



  template <int dim>
  std::string
  Simulator<dim>::what_is_left() const
  {
    if (last_checkpoint == 0)
      return "no checkpoint was written yet: make room (free space, or raise "
             "the quota) and run again";
    return "the last complete checkpoint (increment " +
           std::to_string(last_checkpoint) + ", t = " +
           Input::to_text(driver.times()[last_checkpoint - 1]) + ") in '" +
           checkpoint.path() +
           "' stays valid: make room (free space, or raise the quota) and "
           "resume with 'set Resume computation = auto'";
  }



  template <int dim>
  void
  Simulator<dim>::stop_on_signal(const int signal)
  {
    const std::string name = RunControl::signal_name(signal);
    const unsigned int n   = driver.times().size();
    if (n_finished == 0)
      throw StoppedBySignal(
        "stopped by " + name +
        " during increment 1: no increment finished, nothing to checkpoint; "
        "run again from the start");
    if (last_checkpoint != n_finished)
      save_checkpoint(n_finished - 1);
    throw StoppedBySignal(
      "stopped by " + name + " after increment " + std::to_string(n_finished) +
      " of " + std::to_string(n) +
      " (t = " + Input::to_text(driver.times()[n_finished - 1]) +
      "), its checkpoint in '" + checkpoint.path() +
      "': run again with 'set Resume computation = auto' (or true) to go on");
  }



  template <int dim>
  IncrementOutcome<dim>
  Simulator<dim>::solve_on_current_mesh(const unsigned int    l,
                                        const WarmStart<dim> *from_coarser)
  {
    const double t           = driver.times()[l];
    const double load_factor = driver.loading().load_factor(t);
    const double load_factor_start =
      driver.loading().load_factor(driver.start_time(l));
    const auto solve = [&](const WarmStart<dim> *first_start) {
      return solve_with_settled_pair_geometry<dim>(model, state.u, driver.start_time(l), t,
                                 [&](const WarmStart<dim> *warm_start) {
        return increment_solver.solve(model,
                                      state,
                                      l + 1,
                                      driver.start_time(l),
                                      t,
                                      load_factor_start,
                                      load_factor,
                                      postprocessors.needs_history(),
                                      *timer,
                                      warm_start ? warm_start : first_start);
      });
    };
    IncrementOutcome<dim> outcome = solve(from_coarser);
    if (!outcome.statistics.converged &&
        (from_coarser != nullptr || increment_solver.started_from_last_increment()))
      {
        // The last increment's motion, or the coarser mesh's solution, may
        // lead the start where the method cannot converge (a cell
        // inverted, the contact state turned) even where the prescribed
        // motion goes on: the increment again from no motion, before it is
        // cut, the work of both solves counted.
        const SolveStatistics first = outcome.statistics;
        increment_solver.forget_last_increment();
        outcome = solve(nullptr);
        outcome.statistics.add_work(first);
      }
    const SolveStatistics &statistics = outcome.statistics;
    if (!statistics.converged)
      {
        const ContactSummary<dim>             no_contact;
        const Postprocess::IncrementResult<dim> result{
          l + 1, unsigned(driver.times().size()), t, load_factor,
          model,  state, outcome, no_contact};
        postprocessors.execute_failed(result);
        const Residuals &res = statistics.residuals;
        throw SolverError(
          "increment " + std::to_string(l + 1) + " (t = " + Input::to_text(t) +
          "): " + statistics.failure + ". Residuals: force balance " +
          Input::scientific(res.force_balance) + ", complementarity " +
          Input::scientific(res.complementarity) + ", penetration " +
          Input::scientific(res.penetration) +
          (statistics.worst_places.empty() ? "" : "; " + statistics.worst_places) +
          ". The increments before it are written; this one is not");
      }
    return outcome;
  }



  template <int dim>
  bool
  Simulator<dim>::adapt_mesh(const IncrementOutcome<dim> &outcome,
                             const unsigned int           cycle,
                             WarmStart<dim>              &from_coarser)
  {
    TimerOutput::Scope scope(*timer, "Mesh refinement");
    const ElasticBody<dim>     &body    = model.get_body();
    const ContactOperator<dim> &contact = model.get_contact();
    TrilinosWrappers::MPI::Vector solution = state.u;
    solution += outcome.du;
    TrilinosWrappers::MPI::Vector solution_ghosted = body.make_ghosted_vector();
    solution_ghosted                               = solution;

    // The contact forces of the state and of the solve go over as
    // tractions (force per nodal area), which do not depend on the mesh;
    // the solve's increment as it is.
    const auto traction_field = [&](const auto &cartesian_force) {
      std::vector<Tensor<1, dim>> tractions(contact.n_local());
      for (unsigned int j = 0; j < contact.n_local(); ++j)
        tractions[j] = cartesian_force(j) / contact.nodal_area(j);
      TrilinosWrappers::MPI::Vector field = body.make_vector();
      contact.set_nodal_values(tractions, field);
      return field;
    };
    TrilinosWrappers::MPI::Vector state_tractions =
      traction_field([&](const unsigned int j) { return state.contact_forces[j]; });
    TrilinosWrappers::MPI::Vector solved_tractions =
      traction_field([&](const unsigned int j) {
        return contact.to_cartesian(j, outcome.reactions[j]);
      });
    from_coarser.du = outcome.du;

    const bool changed = model.adapt(
      [&](parallel::distributed::Triangulation<dim> &mesh) {
        const bool flagged = adaptivity.mark(
          mesh, body, solution_ghosted, contact, outcome.results);
        if (flagged)
          increment_solver.release();
        return flagged;
      },
      {&state.u, &state_tractions, &from_coarser.du, &solved_tractions});
    if (!changed)
      return false;
    const auto forces_of = [&](const TrilinosWrappers::MPI::Vector &field) {
      std::vector<Tensor<1, dim>> forces(contact.n_local());
      for (unsigned int j = 0; j < contact.n_local(); ++j)
        forces[j] = contact.nodal_value(j, field) * contact.nodal_area(j);
      return forces;
    };
    state.contact_forces = forces_of(state_tractions);
    from_coarser.forces  = forces_of(solved_tractions);
    model.assemble();
    increment_solver.initialize(model);
    pcout << "  mesh refinement " << cycle + 1 << ": "
          << model.mesh().n_global_active_cells() << " cells, d = "
          << body.n_free_dofs() << ", c = " << contact.n_candidates()
          << std::endl;
    return true;
  }



  template <int dim>
  unsigned int
  Simulator<dim>::solve_increment(const unsigned int l)
  {
    const double t           = driver.times()[l];
    const double load_factor = driver.loading().load_factor(t);
    ContactOperator<dim> &contact = model.get_contact();
    contact.move_obstacle(contact.obstacle_displacement(t));

    IncrementOutcome<dim> outcome = solve_on_current_mesh(l);
    // Each solve on a refined mesh starts from the last one's, as step-42
    // does (on the step-42 scene's last mesh, 1 rank: 7 Newton steps and
    // 115 Krylov iterations instead of 24 and 417 from the state).
    WarmStart<dim> from_coarser;
    for (unsigned int cycle = 0;
         adaptivity.due(l + 1, cycle, model.get_body().n_free_dofs()) &&
         adapt_mesh(outcome, cycle, from_coarser);
         ++cycle)
      outcome = solve_on_current_mesh(l, &from_coarser);

    for (unsigned int j = 0; j < contact.n_local(); ++j)
      state.contact_forces[j] = contact.to_cartesian(j, outcome.reactions[j]);
    state.u += outcome.du;
    model.commit(state.u);

    ContactSummary<dim> summary = summarize(contact,
                                            outcome.results,
                                            state.contact_forces,
                                            model.get_materials().axisymmetric(),
                                            mpi_communicator);
    if (contact.active())
      {
        TrilinosWrappers::MPI::Vector u_ghosted =
          model.get_body().make_ghosted_vector();
        u_ghosted = state.u;
        summary.deepest_penetration =
          contact.deepest_boundary_penetration(model.get_body(), u_ghosted);
      }
    const unsigned int n = driver.times().size();
    const Postprocess::IncrementResult<dim> result{
      l + 1, n, t, load_factor, model, state, outcome, summary};
    Postprocess::print_increment(pcout,
                                 result,
                                 increment_solver.iteration_name(),
                                 increment_solver.last_linear_solve());
    if (result.last())
      Postprocess::print_final_state(pcout, result);

    TimerOutput::Scope scope(*timer, "Output");
    // The parameters go with the first results, so that a run that fails
    // before leaves an existing output folder as it was.
    if (l == 0 && postprocessors.writes_files())
      run_on_root(mpi_communicator, [&]() {
        write_file_atomically(output_directory + "/parameters.prm",
                              parameters_as_run);
      });
    postprocessors.execute(result);
    n_finished = l + 1;
    return outcome.statistics.iterations;
  }



  template <int dim>
  void
  Simulator<dim>::finish_increment(const unsigned int l)
  {
    if (postprocessors.checkpoint_due(l + 1, driver.times().size()))
      {
        TimerOutput::Scope scope(*timer, "Output");
        save_checkpoint(l);
      }
    // A signal stops the run here, once the increment is written; an
    // urgent one stops the contact solver earlier.
    if (const int signal = RunControl::stop_signal(mpi_communicator))
      throw StopRequested(signal);
  }



  template <int dim>
  void
  Simulator<dim>::print_summary() const
  {
    Utilities::System::MemoryStats memory;
    Utilities::System::get_memory_stats(memory);
    pcout << "-- summary:";
    for (const auto &[section, seconds] :
         timer->get_summary_data(TimerOutput::total_wall_time))
      pcout << ' ' << section << " = "
            << Utilities::MPI::max(seconds, mpi_communicator) << " s;";
    const ShiftedStiffnessSolver &linear = increment_solver.get_linear_solver();
    pcout << " (within the solves: AMG set-up = "
          << Utilities::MPI::max(linear.amg_setup_wall_time(), mpi_communicator)
          << " s; Krylov solves = "
          << Utilities::MPI::max(linear.krylov_seconds, mpi_communicator)
          << " s;";
    if (linear.multigrid_setup_seconds > 0)
      pcout << " multigrid set-up = "
            << Utilities::MPI::max(linear.multigrid_setup_seconds, mpi_communicator)
            << " s;";
    if (linear.n_factorizations > 0)
      pcout << " Cholesky factorizations = "
            << Utilities::MPI::max(linear.factorization_seconds, mpi_communicator)
            << " s; (" << linear.n_factorizations << " of them)";
    pcout << ")";
    pcout << " peak memory = "
          << Utilities::MPI::max(memory.VmHWM, mpi_communicator) / 1024.
          << " MB per rank (largest)" << std::endl;
  }



  template <int dim>
  void
  Simulator<dim>::save_checkpoint(const unsigned int l)
  {
    const ElasticBody<dim>       &body      = model.get_body();
    TrilinosWrappers::MPI::Vector u_ghosted = body.make_ghosted_vector();
    u_ghosted                               = state.u;
    // The contact forces as a nodal field, so that they move with the mesh.
    TrilinosWrappers::MPI::Vector forces = body.make_vector();
    model.get_contact().set_nodal_values(state.contact_forces, forces);
    TrilinosWrappers::MPI::Vector forces_ghosted = body.make_ghosted_vector();
    forces_ghosted                               = forces;

    std::ostringstream            text;
    boost::archive::text_oarchive archive(text);
    const unsigned int            n_done = l + 1;
    const std::string             written = postprocessors.save_state();
    archive << n_done << driver.times() << written;
    checkpoint.save(model.mesh(),
                    body.get_dof_handler(),
                    {&u_ghosted, &forces_ghosted},
                    model.get_history(),
                    text.str(),
                    parameters_as_run);
    last_checkpoint = n_done;
  }



  template <int dim>
  unsigned int
  Simulator<dim>::load_checkpoint()
  {
    const ContactOperator<dim>   &contact = model.get_contact();
    TrilinosWrappers::MPI::Vector forces  = model.get_body().make_vector();
    std::vector<TrilinosWrappers::MPI::Vector *> vectors = {&state.u, &forces};
    checkpoint.load_vectors(model.get_body().get_dof_handler(), vectors);
    model.load_history();
    for (unsigned int j = 0; j < contact.n_local(); ++j)
      state.contact_forces[j] = contact.nodal_value(j, forces);

    std::istringstream            text(checkpoint.load_state());
    boost::archive::text_iarchive archive(text);
    unsigned int                  n_done = 0;
    std::vector<double>           times;
    std::string                   written;
    archive >> n_done >> times >> written;
    driver.restore_times(times);
    postprocessors.load_state(written);
    if (n_done >= times.size() && resume_if_possible)
      return n_done;
    if (n_done >= times.size())
      throw InputError("<Resume computation>: the checkpoint in '" +
                       checkpoint.path() + "' is of the last increment (" +
                       std::to_string(n_done) + " of " +
                       std::to_string(times.size()) +
                       "): the run is complete; set Resume computation = "
                       "false to run it again (auto: nothing to do)");
    pcout << "Resuming after increment " << n_done << " (t = "
          << Input::to_text(times[n_done - 1]) << ") from "
          << checkpoint.path() << std::endl;
    return n_done;
  }

  template class Simulator<2>;
  template class Simulator<3>;
} // namespace FrictionalContact
