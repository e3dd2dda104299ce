#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_tools.h>

#include <frictional_contact/files.h>
#include <frictional_contact/plugins.h>
#include <frictional_contact/simulator.h>
#include <frictional_contact/stiffness_spectrum.h>

#include <boost/archive/text_iarchive.hpp>
#include <boost/archive/text_oarchive.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <fstream>
#include <cstdlib>
#include <iomanip>
#include <sstream>

namespace FrictionalContact
{
  namespace
  {
    /// "(0, -0.01)"
    template <int dim>
    std::string
    to_text(const Tensor<1, dim> &v)
    {
      std::string text = "(";
      for (unsigned int d = 0; d < dim; ++d)
        text += (d == 0 ? "" : ", ") + Input::to_text(v[d]);
      return text + ")";
    }

    std::string
    percent(const unsigned int part, const types::global_dof_index whole)
    {
      std::ostringstream out;
      out << std::fixed << std::setprecision(1)
          << (whole > 0 ? 100. * part / whole : 0.) << '%';
      return out.str();
    }

    /// Boundary ids present in the distributed mesh (on any rank).
    template <int dim>
    std::set<types::boundary_id>
    boundary_ids_in(const parallel::distributed::Triangulation<dim> &mesh)
    {
      std::set<types::boundary_id> ids;
      for (const auto &cell : mesh.active_cell_iterators())
        if (!cell->is_artificial())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              ids.insert(face->boundary_id());
      return Utilities::MPI::compute_set_union(ids, mesh.get_communicator());
    }
  } // namespace



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

    prm.enter_subsection("Geometry");
    PluginRegistry<Geometry::Interface<dim>>::declare_parameters(
      prm, "box", "The shape of the elastic body and its boundary names.");
    prm.declare_entry("Global refinements",
                      "0",
                      Patterns::Integer(0, 12),
                      "How often every cell of the geometry's mesh is split "
                      "in 2^dim (0 to 12).");
    prm.declare_entry("Local refinements",
                      "0",
                      Patterns::Integer(0, 12),
                      "After the global refinements, how often the cells "
                      "near Refinement center are split again (0 to 12), "
                      "for example around the contact zone. Hanging nodes "
                      "between the levels are constrained; keep them out "
                      "of the contact zone (they are not contact "
                      "candidates).");
    prm.declare_entry("Refinement center",
                      dim == 2 ? "0, 0" : "0, 0, 0",
                      Patterns::Anything(),
                      "Centre of the region of local refinement (length).");
    prm.declare_entry("Refinement radius",
                      "0",
                      Patterns::Double(0.),
                      "Cells reaching closer than this to Refinement center "
                      "are refined locally (length, >= 0).");
    prm.leave_subsection();

    LinearElasticMaterial<dim>::declare_parameters(prm);
    BoundaryConditions<dim>::declare_parameters(prm);
    ContactOperator<dim>::declare_parameters(prm);
    LoadingHistory::declare_parameters(prm);

    prm.enter_subsection("Contact solver");
    PluginRegistry<ContactSolver<dim>>::declare_parameters(
      prm,
      "semismooth Newton",
      "The method that solves each incremental contact problem.",
      "Method");
    prm.declare_entry("Report every",
                      "0",
                      Patterns::Integer(0),
                      "Print the residuals every this many iterations of the "
                      "contact solver (0: only one line per increment).");
    prm.declare_entry("Eigenvalue tolerance",
                      "1e-8",
                      Patterns::Double(0., 1.),
                      "Relative accuracy of mu_pi, the smallest eigenvalue "
                      "of K, which sets the acceleration of Algorithm 2.");
    prm.declare_entry("Try the elastic solution first",
                      "true",
                      Patterns::Bool(),
                      "Before the contact iteration of an increment, solve "
                      "K du = p once: if no candidate then reaches the "
                      "obstacle, this is the solution (every node free, "
                      "r = 0) and the iteration is skipped. Algorithm 2 "
                      "converges very slowly when nothing touches.");
    prm.declare_entry("Lanczos vectors",
                      "20",
                      Patterns::Integer(4),
                      "Lanczos vectors PARPACK keeps while computing mu_pi "
                      "(>= 4).");
    prm.leave_subsection();
    ShiftedStiffnessSolver::declare_parameters(prm);

    OutputWriter<dim>::declare_parameters(prm);
    StatisticsFile::declare_parameters(prm);
    FclibExport::declare_parameters(prm);
    prm.enter_subsection("Output");
    prm.declare_entry("Checkpoint every",
                      "1",
                      Patterns::Integer(0),
                      "With more than one increment, save the state for "
                      "<Resume computation> after every n-th increment "
                      "(0: never).");
    prm.declare_entry("Write convergence history",
                      "false",
                      Patterns::Bool(),
                      "Write history-NNNNN.txt for each increment: one row "
                      "per primal-dual iteration with the wall time, the "
                      "three residuals, |du_k+1 - du_k| and the CG "
                      "iterations (see scripts/plot_history.py).");
    prm.leave_subsection();
  }



  template <int dim>
  Simulator<dim>::Simulator(ParameterHandler &prm, const MPI_Comm comm)
    : mpi_communicator(comm)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
    , output_directory(prm.get("Output directory"))
    , triangulation(comm)
    , geometry([&]() {
      prm.enter_subsection("Geometry");
      auto model = PluginRegistry<Geometry::Interface<dim>>::create(prm);
      prm.leave_subsection();
      return model;
    }())
    , boundary_names([&]() {
      geometry->create_coarse_mesh(triangulation);
      return BoundaryNames(geometry->boundary_names(),
                           boundary_ids_in(triangulation));
    }())
    , material(prm)
    , boundary_conditions(prm, boundary_names)
    , body(triangulation, material, boundary_conditions)
    , contact(prm, boundary_names)
    , linear_solver(prm)
    , contact_solver([&]() {
      prm.enter_subsection("Contact solver");
      auto method = PluginRegistry<ContactSolver<dim>>::create(prm, "Method");
      method->set_output(pcout, prm.get_integer("Report every"));
      prm.leave_subsection();
      return method;
    }())
    , output(prm, output_directory)
    , statistics(prm, output_directory, comm)
    , fclib_export(prm, output_directory)
    , loading(prm)
    , checkpoint(output_directory, comm)
  {
    prm.enter_subsection("Geometry");
    global_refinements = prm.get_integer("Global refinements");
    local_refinements  = prm.get_integer("Local refinements");
    local_refinement_center = Point<dim>(Input::parse_vector<dim>(
      "Geometry/Refinement center", prm.get("Refinement center")));
    local_refinement_radius = prm.get_double("Refinement radius");
    if (local_refinements > 0 && !(local_refinement_radius > 0))
      Input::fail("Geometry/Refinement radius",
                  prm.get("Refinement radius"),
                  "Local refinements > 0 needs a positive radius");
    prm.leave_subsection();
    const std::string resume_choice = prm.get("Resume computation");
    resume = resume_choice == "true" ||
             (resume_choice == "auto" && checkpoint.exists());

    prm.enter_subsection("Contact solver");
    eigenvalue_tolerance = prm.get_double("Eigenvalue tolerance");
    lanczos_vectors      = prm.get_integer("Lanczos vectors");
    try_elastic_first    = prm.get_bool("Try the elastic solution first");
    prm.leave_subsection();
    prm.enter_subsection("Loading");
    cut_on_failure = prm.get("On failure") == "cut increment";
    maximum_cuts   = prm.get_integer("Maximum cuts");
    prm.leave_subsection();
    times = loading.increment_times();
    fclib_export.check_increments(times.size());
    prm.enter_subsection("Output");
    write_history    = prm.get_bool("Write convergence history");
    checkpoint_every = times.size() > 1 ?
                         prm.get_integer("Checkpoint every") :
                         0;
    prm.leave_subsection();

    std::ostringstream parameters;
    prm.print_parameters(parameters, ParameterHandler::ShortPRM);
    parameters_as_run = parameters.str();
  }



  template <int dim>
  void
  Simulator<dim>::check_memory(const double n_cells) const
  {
    // Measured: about 3 kB per cell in 2D and 14 kB in 3D (matrix, AMG,
    // vectors, mesh), on top of some 170 MB for the libraries.
    const double needed = n_cells * (dim == 2 ? 3e3 : 1.4e4);
    double       available = 0;
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      {
        std::ifstream meminfo("/proc/meminfo");
        std::string   key;
        double        kilobytes;
        while (meminfo >> key >> kilobytes)
          if (key == "MemAvailable:")
            available = 1024 * kilobytes;
          else
            meminfo.ignore(1000, '\n');
      }
    available = Utilities::MPI::broadcast(mpi_communicator, available, 0);
    if (available > 0 && needed > 0.8 * available)
      throw InputError("<Geometry>: the mesh would have " +
                       Input::to_text(n_cells) + " cells and need about " +
                       Input::to_text(needed / 1e9) + " GB, but " +
                       Input::to_text(available / 1e9) +
                       " GB are available; use fewer cells (repetitions, "
                       "Global refinements, Local refinements)");
  }



  template <int dim>
  void
  Simulator<dim>::refine_near_center()
  {
    if (local_refinements == 0)
      return;
    const auto near = [&](const auto &cell) {
      return cell->center().distance(local_refinement_center) <
             local_refinement_radius + 0.5 * cell->diameter();
    };
    // Before each level, the final size is estimated from the cells near
    // the center now: each becomes 2^dim per level left, in a band around
    // the disc that narrows with the cells. Measured on the Hertz scenes,
    // the estimate is within 10 % in 2D and up to 1.9 times low in 3D
    // (p4est's 2:1 balance adds cells) from the coarse mesh, and closer at
    // every level, so a mesh that cannot fit is refused while the mesh made
    // so far is still small.
    for (unsigned int i = 0; i < local_refinements; ++i)
      {
        double n_near = 0, diameter = 0;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() && near(cell))
            {
              ++n_near;
              diameter = std::max(diameter, cell->diameter());
            }
        n_near   = Utilities::MPI::sum(n_near, mpi_communicator);
        diameter = Utilities::MPI::max(diameter, mpi_communicator);
        const unsigned int levels_left = local_refinements - i;
        const double       radius      = local_refinement_radius;
        const double       band =
          std::pow((radius + 0.5 * diameter / std::pow(2., levels_left)) /
                     (radius + 0.5 * diameter),
                   dim);
        check_memory(triangulation.n_global_active_cells() +
                     n_near * (std::pow(2., dim * levels_left) - 1) * band);

        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() && near(cell))
            cell->set_refine_flag();
        triangulation.execute_coarsening_and_refinement();
      }
    check_memory(triangulation.n_global_active_cells());
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
          checkpoint.verify(parameters_as_run);
          checkpoint.load_mesh(triangulation);
        }
      else
        {
          const unsigned int refinements =
            geometry->n_built_in_refinements() + global_refinements;
          check_memory(triangulation.n_global_active_cells() *
                       std::pow(2., dim * refinements));
          triangulation.refine_global(refinements);
          refine_near_center();
        }
      body.setup();
      // Every rank must own unknowns: the solvers' collective steps
      // (PARPACK, AMG set-up) do not work with an empty share.
      const types::global_dof_index fewest_owned = Utilities::MPI::min(
        body.get_dof_handler().n_locally_owned_dofs(), mpi_communicator);
      if (fewest_owned == 0)
        throw InputError(
          "the mesh has " + std::to_string(triangulation.n_global_active_cells()) +
          " cells, too few for " +
          std::to_string(Utilities::MPI::n_mpi_processes(mpi_communicator)) +
          " MPI ranks (a rank would own no unknowns): run on fewer ranks, or "
          "use a finer mesh (repetitions, <Geometry/Global refinements>)");
      if (contact.active())
        contact.setup(body, boundary_names);
    }
    {
      TimerOutput::Scope scope(*timer, "Assembly");
      body.assemble();
    }
    body.check_rigid_body_motion_is_prevented();

    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
    pcout << "-- contact " << FRICTIONAL_CONTACT_VERSION << " on deal.II "
          << DEAL_II_PACKAGE_VERSION << ", " << n_ranks << " MPI rank"
          << (n_ranks > 1 ? "s" : "") << std::endl;
    pcout << "Scene: " << dim << "D, " << material.describe() << std::endl;
    pcout << "Mesh: " << triangulation.n_global_active_cells() << " cells; d = "
          << body.n_free_dofs() << " free displacement dofs of "
          << body.get_dof_handler().n_dofs() << std::endl;
    if (contact.active())
      {
        const double      mu = contact.friction_coefficient();
        const std::size_t bytes =
          Utilities::MPI::sum(contact.memory_consumption(), mpi_communicator);
        pcout << "Contact: "
              << (mu > 0 ? "frictional (mu = " + Input::to_text(mu) + ")" :
                           std::string("frictionless (no tangential operator)"))
              << ", c = " << contact.n_candidates() << " candidates on "
              << contact.describe_boundaries(boundary_names) << "; "
              << bytes << " bytes of contact data" << std::endl;
      }
    else
      pcout << "Contact: none (one linear elastic solve)" << std::endl;
    pcout << "Loading: " << loading.describe() << std::endl;
    std::string written = output.describe();
    if (statistics.enabled())
      written += (written.empty() ? "" : ", ") + std::string("statistics");
    pcout << "Output: "
          << (written.empty() ? "nothing" : written + " in " + output_directory + "/")
          << std::endl;
  }



  template <int dim>
  void
  Simulator<dim>::run()
  {
    setup();
    if (output.writes_files() || statistics.enabled() || checkpoint_every > 0 ||
        write_history)
      check_output_directory(output_directory, mpi_communicator);
    linear_solver.initialize(body.stiffness_matrix(), body.rigid_body_modes());
    u = body.make_vector();
    contact_forces.assign(contact.n_local(), Tensor<1, dim>());
    if (resume)
      first_increment = load_checkpoint();

    if (contact.active())
      {
        sigma_T = contact.largest_singular_value();
        pcout << "Solver: " << contact_solver->describe() << std::endl
              << "    sigma_T = " << Input::to_text(sigma_T)
              << " (largest singular value of T)" << std::endl;
      }

    unsigned int cuts = 0;
    for (unsigned int l = first_increment; l < times.size(); ++l)
      try
        {
          solve_increment(l);
          cuts = 0;
        }
      catch (const SolverError &error)
        {
          if (!cut_on_failure || cuts == maximum_cuts)
            throw;
          // Retry from the same state with half the increment.
          const double t_prev = l > 0 ? times[l - 1] : 0.;
          times.insert(times.begin() + l, (t_prev + times[l]) / 2);
          ++cuts;
          pcout << "Cut in half (" << cuts << " of at most " << maximum_cuts
                << " cuts in a row), now " << times.size()
                << " increments, because " << error.what() << std::endl;
          --l;
        }
    timer->print_wall_time_statistics(mpi_communicator);

    // One line for scripts (bench/): seconds per section, peak memory.
    Utilities::System::MemoryStats memory;
    Utilities::System::get_memory_stats(memory);
    pcout << "-- summary:";
    for (const auto &[section, seconds] :
         timer->get_summary_data(TimerOutput::total_wall_time))
      pcout << ' ' << section << " = " << Utilities::MPI::max(seconds, mpi_communicator) << " s;";
    pcout << " peak memory = "
          << Utilities::MPI::max(memory.VmHWM, mpi_communicator) / 1024.
          << " MB per rank (largest)" << std::endl;
  }



  template <int dim>
  double
  Simulator<dim>::smallest_eigenvalue_of_K()
  {
    if (mu_pi > 0)
      return mu_pi;
    TimerOutput::Scope       scope(*timer, "Smallest eigenvalue of K");
    const SmallestEigenvalue eigenvalue =
      compute_smallest_eigenvalue(body.stiffness_matrix(),
                                  linear_solver,
                                  eigenvalue_tolerance,
                                  lanczos_vectors);
    mu_pi = eigenvalue.value;
    pcout << "    mu_pi = " << Input::scientific(mu_pi, 6)
          << " (smallest eigenvalue of K, PARPACK; Rayleigh quotient "
          << Input::scientific(eigenvalue.rayleigh_quotient, 6) << ")" << std::endl
          << "-- mu_pi took " << eigenvalue.n_solves << " solves with K, "
          << eigenvalue.cg_iterations << " CG iterations" << std::endl;
    return mu_pi;
  }



  template <int dim>
  IncrementalProblem<dim>
  Simulator<dim>::incremental_problem(
    const unsigned int                   l,
    const TrilinosWrappers::MPI::Vector &load,
    const TrilinosWrappers::MPI::Vector &start) const
  {
    IncrementalProblem<dim> problem{body.stiffness_matrix(), load, contact};
    problem.largest_singular_value_T = sigma_T;
    const double t      = times[l];
    const double t_prev = l > 0 ? times[l - 1] : 0.;
    const Tensor<1, dim> motion =
      contact.obstacle_displacement(t) - contact.obstacle_displacement(t_prev);
    for (unsigned int j = 0; j < contact.n_local(); ++j)
      {
        // Small deformations: g_j^{l+1} = g_j^0(obstacle at t) - t_n,j^T u^l
        // (with the prescribed part of the increment).
        problem.gaps.push_back(contact.reference_gap(j) -
                               contact.local_part(j, start)[0]);
        Tensor<1, dim> slip = contact.to_local(j, motion);
        slip[0]             = 0;
        problem.obstacle_slip.push_back(slip);
      }
    return problem;
  }



  template <int dim>
  bool
  Simulator<dim>::separates(const IncrementalProblem<dim>       &problem,
                            const TrilinosWrappers::MPI::Vector &du) const
  {
    bool penetrates = false;
    for (unsigned int j = 0; j < contact.n_local() && !penetrates; ++j)
      penetrates = problem.relative_displacement(j, du)[0] > problem.gaps[j];
    return !Utilities::MPI::logical_or(penetrates, mpi_communicator);
  }



  template <int dim>
  SolveStatistics
  Simulator<dim>::solve_increment(const unsigned int l)
  {
    const double t = times[l];
    contact.move_obstacle(contact.obstacle_displacement(t));

    // The increment of the prescribed displacements, and the configuration
    // it leads to before the rest of the increment is solved for.
    const double t_prev = l > 0 ? times[l - 1] : 0.;
    TrilinosWrappers::MPI::Vector lifting = body.make_vector();
    body.prescribed_increment(t_prev, t, lifting);
    Input::require_finite(lifting.l2_norm(),
                          "Boundary conditions/Prescribed displacement", t);
    TrilinosWrappers::MPI::Vector start = u;
    start += lifting;

    // p = p^{l+1} - K (u^l + the prescribed increment).
    TrilinosWrappers::MPI::Vector load = body.make_vector();
    body.internal_force(start, load);
    load.sadd(-1., loading.load_factor(t), body.load_vector());

    TrilinosWrappers::MPI::Vector du = body.make_vector();
    SolveStatistics               result;
    ContactResults<dim>           results;
    if (!contact.active() || try_elastic_first)
      {
        TimerOutput::Scope scope(*timer, "Elastic solve");
        const Timer        wall;
        const unsigned int setups_before = linear_solver.n_amg_setups;
        result.cg_iterations = linear_solver.solve(
          0., du, load, linear_solver.relative_tolerance() * load.l2_norm());
        result.amg_setups = linear_solver.n_amg_setups - setups_before;
        result.seconds    = wall.wall_time();
        if (!std::isfinite(du.l2_norm()))
          throw SolverError("increment " + std::to_string(l + 1) + " (t = " +
                            Input::to_text(t) +
                            "): the elastic solve gave a displacement that is "
                            "not finite");
      }
    if (contact.active())
      {
        IncrementalProblem<dim>     problem = incremental_problem(l, load, start);
        std::vector<Tensor<1, dim>> r(contact.n_local());
        // A length for tolerances that follow the units: the largest gap,
        // displacement so far, or elastic displacement of this increment.
        double largest_gap = 0;
        for (const double g : problem.gaps)
          largest_gap = std::max(largest_gap, std::abs(g));
        problem.length_scale =
          std::max({Utilities::MPI::max(largest_gap, mpi_communicator),
                    start.linfty_norm(),
                    try_elastic_first ? du.linfty_norm() : 0.});
        if (!(problem.length_scale > 0))
          problem.length_scale = 1;
        if (try_elastic_first && separates(problem, du))
          {
            TrilinosWrappers::MPI::Vector K_du = body.make_vector();
            TrilinosWrappers::MPI::Vector no_force = body.make_vector();
            TrilinosWrappers::MPI::Vector scratch  = body.make_vector();
            body.stiffness_matrix().vmult(K_du, du);
            result.residuals =
              compute_residuals(problem, du, K_du, no_force, r, scratch);
            result.converged = true;
          }
        else
          {
            // Warm start: the reactions of the previous increment, du = 0.
            for (unsigned int j = 0; j < contact.n_local(); ++j)
              r[j] = contact.friction_cone().project(
                contact.to_local(j, contact_forces[j]));
            du = 0;
            if (contact_solver->needs_smallest_eigenvalue())
              problem.smallest_eigenvalue_K = smallest_eigenvalue_of_K();
            const SolveStatistics elastic = result;
            {
              TimerOutput::Scope scope(*timer, "Contact solve");
              result = contact_solver->solve(
                problem, linear_solver, du, r, write_history);
            }
            result.cg_iterations += elastic.cg_iterations;
            result.amg_setups += elastic.amg_setups;
            result.seconds += elastic.seconds;
          }
        if (fclib_export.wanted(l + 1))
          fclib_export.write(l + 1, problem, contact, du, r, result.converged);
        if (!result.converged)
          {
            const Residuals &res = result.residuals;
            throw SolverError(
              "increment " + std::to_string(l + 1) + " (t = " +
              Input::to_text(t) + "): " + result.failure +
              ". Residuals: force balance " + Input::scientific(res.force_balance) +
              ", complementarity " + Input::scientific(res.complementarity) +
              ", penetration " + Input::scientific(res.penetration) +
              ". The increments before it are written; this one is not");
          }
        results = contact_results(problem, du, r);
        for (unsigned int j = 0; j < contact.n_local(); ++j)
          contact_forces[j] = contact.to_cartesian(j, r[j]);
      }
    else
      {
        result.iterations = 1;
        result.converged  = true;
      }
    body.get_constraints().distribute(du);
    du += lifting;
    u += du;
    report_increment(l, du, results, result);
    return result;
  }



  template <int dim>
  ContactResults<dim>
  Simulator<dim>::contact_results(const IncrementalProblem<dim>       &problem,
                                  const TrilinosWrappers::MPI::Vector &du,
                                  const std::vector<Tensor<1, dim>>   &r) const
  {
    ContactResults<dim> results;
    results.reaction = r;
    for (unsigned int j = 0; j < contact.n_local(); ++j)
      {
        results.reaction_increment.push_back(
          r[j] - contact.to_local(j, contact_forces[j]));
        results.local_displacement.push_back(problem.relative_displacement(j, du));
        results.gap.push_back(problem.gaps[j] -
                              results.local_displacement.back()[0]);
        results.state.push_back(contact.friction_cone().state(r[j]));
        const double area = contact.nodal_area(j);
        results.pressure.push_back(area > 0 ? -r[j][0] / area : 0.);
      }
    return results;
  }



  template <int dim>
  void
  Simulator<dim>::report_increment(const unsigned int                   l,
                                   const TrilinosWrappers::MPI::Vector &du,
                                   const ContactResults<dim>           &results,
                                   const SolveStatistics               &result)
  {
    const double       t      = times[l];
    const unsigned int n      = times.size();
    const bool         last   = l + 1 == n;

    // Counts of free / stick / slip and the total contact force.
    unsigned int   counts[3] = {0, 0, 0};
    Tensor<1, dim> contact_force;
    double         normal_force = 0;
    Tensor<1, dim> tangential_force;
    // Areas of the nodes in contact and of those sticking (lumped nodal
    // areas, see ContactOperator::nodal_area), the largest pressure.
    double contact_area = 0, stick_area = 0, max_pressure = 0;
    for (unsigned int j = 0; j < results.state.size(); ++j)
      {
        ++counts[static_cast<int>(results.state[j])];
        if (results.state[j] != ContactState::free)
          contact_area += contact.nodal_area(j);
        if (results.state[j] == ContactState::stick)
          stick_area += contact.nodal_area(j);
        max_pressure = std::max(max_pressure, results.pressure[j]);
        contact_force += contact_forces[j];
        normal_force -= results.reaction[j][0];
        Tensor<1, dim> normal_part;
        normal_part[0] = results.reaction[j][0];
        tangential_force += contact_forces[j] - contact.to_cartesian(j, normal_part);
      }
    Utilities::MPI::sum(counts, mpi_communicator, counts);
    contact_force    = Utilities::MPI::sum(contact_force, mpi_communicator);
    normal_force     = Utilities::MPI::sum(normal_force, mpi_communicator);
    tangential_force = Utilities::MPI::sum(tangential_force, mpi_communicator);
    contact_area     = Utilities::MPI::sum(contact_area, mpi_communicator);
    stick_area       = Utilities::MPI::sum(stick_area, mpi_communicator);
    max_pressure     = Utilities::MPI::max(max_pressure, mpi_communicator);

    const Residuals &res = result.residuals;
    pcout << "Increment " << l + 1 << "/" << n << ", t = " << Input::to_text(t);
    if (contact.active() && result.iterations == 0)
      pcout << ": nothing touches, the elastic solution (" << result.cg_iterations
            << " CG iterations); residuals " << Input::scientific(res.force_balance)
            << ' ' << Input::scientific(res.complementarity) << ' '
            << Input::scientific(res.penetration) << std::endl;
    else if (contact.active())
      pcout << ": " << result.iterations << ' '
            << contact_solver->iteration_name() << " iterations, "
            << result.cg_iterations << " CG iterations, " << result.amg_setups
            << " AMG set-ups; residuals " << Input::scientific(res.force_balance)
            << ' ' << Input::scientific(res.complementarity) << ' '
            << Input::scientific(res.penetration) << "; free/slip/stick " << counts[0]
            << '/' << counts[2] << '/' << counts[1] << std::endl;
    else
      pcout << ": elastic solve, " << result.cg_iterations << " CG iterations ("
            << linear_solver.last_preconditioner << ")" << std::endl;
    pcout << "-- increment " << l + 1 << " solve wall time " << result.seconds
          << " s" << std::endl;

    if (last)
      {
        TrilinosWrappers::MPI::Vector u_ghosted = body.make_ghosted_vector();
        u_ghosted                               = u;
        const Tensor<1, dim> support =
          body.support_reaction(u_ghosted, loading.load_factor(t));
        const Tensor<1, dim> load =
          loading.load_factor(t) * body.total_load();
        const types::global_dof_index c = contact.n_candidates();
        pcout << "State at t = " << Input::to_text(t) << ":" << std::endl;
        if (contact.active())
          pcout << "    residuals: force balance "
                << Input::scientific(res.force_balance) << ", complementarity "
                << Input::scientific(res.complementarity) << ", penetration "
                << Input::scientific(res.penetration) << std::endl
                << "    candidates: " << percent(counts[0], c) << " free, "
                << percent(counts[2], c) << " slip, " << percent(counts[1], c)
                << " stick (" << counts[0] << " / " << counts[2] << " / "
                << counts[1] << " of " << c << ")" << std::endl;
        pcout << "    force balance: load " << to_text(load) << " + contact "
              << to_text(contact_force) << " + supports " << to_text(support)
              << " = " << Input::scientific((load + contact_force + support).norm())
              << std::endl
              << "    max |u| = " << Input::to_text(u.linfty_norm()) << std::endl;
      }

    TimerOutput::Scope scope(*timer, "Output");
    // The parameters go with the first results, so that a run that fails
    // before leaves an existing output folder as it was.
    if (l == 0 && (output.writes_files() || statistics.enabled()))
      run_on_root(mpi_communicator, [&]() {
        write_file_atomically(output_directory + "/parameters.prm", parameters_as_run);
      });
    output.write(l + 1, t, last, body, contact, material, u, results);

    statistics.add("Increment", l + 1);
    statistics.add("Time", t);
    statistics.add("Load factor", loading.load_factor(t));
    statistics.add("Free dofs d", static_cast<std::uint64_t>(body.n_free_dofs()));
    statistics.add("Contact candidates c",
                   static_cast<std::uint64_t>(contact.active() ? contact.n_candidates() : 0));
    statistics.add("Contact solver iterations", result.iterations);
    statistics.add("CG iterations", result.cg_iterations);
    statistics.add("AMG setups", result.amg_setups);
    statistics.add("Solve wall time (s)", result.seconds);
    statistics.add_scientific("Force balance residual", res.force_balance);
    statistics.add_scientific("Complementarity residual", res.complementarity);
    statistics.add_scientific("Penetration residual", res.penetration);
    statistics.add("Free nodes", counts[0]);
    statistics.add("Stick nodes", counts[1]);
    statistics.add("Slip nodes", counts[2]);
    for (unsigned int d = 0; d < dim; ++d)
      statistics.add_scientific(std::string("Contact force ") + "xyz"[d],
                                contact_force[d]);
    statistics.add_scientific("Normal contact force", normal_force);
    statistics.add_scientific("Tangential contact force", tangential_force.norm());
    statistics.add_scientific("Contact area", contact_area);
    statistics.add_scientific("Stick area", stick_area);
    statistics.add_scientific("Max contact pressure", max_pressure);
    statistics.add_scientific("Max displacement", u.linfty_norm());
    statistics.add_scientific("Max displacement increment", du.linfty_norm());
    statistics.write();

    if (write_history && !result.history.empty())
      run_on_root(mpi_communicator, [&]() {
        std::ostringstream text;
        text << "# Convergence history of increment " << l + 1 << " (t = " << t
             << "): one row per primal-dual iteration.\n"
             << "# iteration seconds force_balance complementarity "
                "penetration step cg_iterations\n"
             << std::setprecision(9);
        for (const HistoryRow &row : result.history)
          text << row.iteration << ' ' << row.seconds << ' '
               << row.residuals.force_balance << ' '
               << row.residuals.complementarity << ' '
               << row.residuals.penetration << ' ' << row.step << ' '
               << row.cg_iterations << '\n';
        std::ostringstream name;
        name << output_directory << "/history-" << std::setw(5)
             << std::setfill('0') << l + 1 << ".txt";
        write_file_atomically(name.str(), text.str());
      });

    if (checkpoint_every > 0 && ((l + 1) % checkpoint_every == 0 || last))
      save_checkpoint(l);
  }



  template <int dim>
  void
  Simulator<dim>::save_checkpoint(const unsigned int l) const
  {
    TrilinosWrappers::MPI::Vector u_ghosted = body.make_ghosted_vector();
    u_ghosted                               = u;
    // The contact forces as a nodal field, so that they move with the mesh.
    TrilinosWrappers::MPI::Vector forces = body.make_vector();
    contact.set_nodal_values(contact_forces, forces);
    TrilinosWrappers::MPI::Vector forces_ghosted = body.make_ghosted_vector();
    forces_ghosted                               = forces;

    std::ostringstream             state;
    boost::archive::text_oarchive archive(state);
    const unsigned int             n_done = l + 1;
    archive << n_done << times << statistics << output;
    checkpoint.save(triangulation,
                    body.get_dof_handler(),
                    {&u_ghosted, &forces_ghosted},
                    state.str(),
                    parameters_as_run);
  }



  template <int dim>
  unsigned int
  Simulator<dim>::load_checkpoint()
  {
    TrilinosWrappers::MPI::Vector forces = body.make_vector();
    std::vector<TrilinosWrappers::MPI::Vector *> vectors = {&u, &forces};
    checkpoint.load_vectors(body.get_dof_handler(), vectors);
    for (unsigned int j = 0; j < contact.n_local(); ++j)
      contact_forces[j] = contact.nodal_value(j, forces);

    std::istringstream             state(checkpoint.load_state());
    boost::archive::text_iarchive archive(state);
    unsigned int                   n_done = 0;
    archive >> n_done >> times >> statistics >> output;
    if (n_done >= times.size())
      throw InputError("<Resume computation>: the checkpoint in '" +
                       checkpoint.path() + "' is of the last increment (" +
                       std::to_string(n_done) + " of " +
                       std::to_string(times.size()) +
                       "): the run is complete; set Resume computation = "
                       "false to run it again");
    pcout << "Resuming after increment " << n_done << " (t = "
          << Input::to_text(times[n_done - 1])
          << ") from " << checkpoint.path() << std::endl;
    return n_done;
  }

  template class Simulator<2>;
  template class Simulator<3>;
} // namespace FrictionalContact
