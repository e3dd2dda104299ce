// IncrementSolver's set-up: the linear solver on the model's body (its
// AMG or geometric multigrid), the checks of the method against the
// scene, and the smallest eigenvalue of K that Kanno's method needs.
#include <frictional_contact/base/input.h>
#include <frictional_contact/driver/increment_solver.h>
#include <frictional_contact/solvers/stiffness_spectrum.h>

namespace FrictionalContact
{
  template <int dim>
  void
  IncrementSolver<dim>::initialize(const Model<dim> &model)
  {
    const ElasticBody<dim>     &body    = model.get_body();
    const ContactOperator<dim> &contact = model.get_contact();
    mortar.reset();
    preconditioner_basis.reset();
    preconditioner_matrix = nullptr;
    krylov_per_step_after_build = 0;
    rebuild_for_tangent         = false;
    linear_solver.set_geometric_multigrid(nullptr, nullptr);
    mortar_cycle.reset();
    geometric.reset();
    geometric_with_springs.reset();
    if (!contact.has_pairs())
      initialize_on_body(body);
    // The cycles of K in u; with contact pairs each increment's K_w gets
    // them through its basis (MortarPreconditioner).
    if (linear_solver.wants_geometric_multigrid())
      make_geometric_multigrid(model);
    mu_pi = 0;
    if (contact.active())
      sigma_T = contact.largest_singular_value();
    contact_active = contact.active();
    const std::set<types::material_id> &held = model.bodies_held_by_contact_alone();
    if (!held.empty() && !solver.method->handles_contact_held_bodies())
      throw InputError(
        "<Contact solver/Method> = " + solver.method_name +
        " needs K positive definite (mu_pi), but only contact holds the body '" +
        body.body_name(*held.begin()) +
        "' against rigid-body motion: set <Contact solver/Method> = "
        "semismooth Newton, which solves such scenes, or hold the body with "
        "<Boundary conditions/Fixed boundaries>");
    if (model.nonlinear() && !solver.method->handles_nonlinear_laws())
      throw InputError(
        "<Contact solver/Method> = " + solver.method_name +
        " is a method for linear elasticity (mu_pi and the second-order cone "
        "program of the paper), but a body is nonlinear (" +
        body.get_materials().describe_nonlinearity() +
        "): set <Contact solver/Method> = "
        "semismooth Newton, which solves the internal force's Newton "
        "equations with the contact conditions");
    const double contrast = body.get_materials().largest_modulus_ratio();
    const double reachable = solver.method->largest_modulus_ratio();
    if (contact.has_pairs() && contrast > reachable)
      throw InputError(
        "<Contact solver/Method> = " + solver.method_name +
        " does not reach its tolerance where the bodies' Young's moduli "
        "differ by more than a factor of " + Utilities::to_string(reachable) +
        " (here " + Utilities::to_string(contrast) +
        "): set <Contact solver/Method> = semismooth Newton, which solves "
        "such pairs");
    if (held.size() > ContactHeldBodies::max_bodies)
      throw InputError("only contact holds " + std::to_string(held.size()) +
                       " bodies; at most " +
                       std::to_string(ContactHeldBodies::max_bodies) +
                       " are supported: hold some with <Boundary "
                       "conditions/Fixed boundaries>");
  }



  template <int dim>
  void
  IncrementSolver<dim>::make_geometric_multigrid(const Model<dim> &model)
  {
    const ElasticBody<dim> &body = model.get_body();
    // A body with a volumetric split (B-bar, nearly incompressible): the
    // mixed solves precondition its A, whose coarse levels are those of a
    // compressible body; its condensed K has no level operators here.
    const bool split = body.volumetric_split().reduced_stiffness != nullptr;
    if (split && !linear_solver.solves_mixed())
      {
        pcout << "Geometric multigrid: not for the condensed stiffness of a "
                 "B-bar body (<Nearly incompressible solves> = condensed); "
                 "the solves take the AMG (Trilinos ML) instead"
              << std::endl;
        return;
      }
    geometric = std::make_unique<GeometricMultigrid<dim>>();
    geometric->initialize(body.get_dof_handler(),
                          model.held_boundaries(),
                          split ? body.reduced_lame_parameters() :
                                  body.lame_parameters(),
                          body.get_constraints(),
                          body.stiffness(),
                          linear_solver.multigrid_smoother_degree());
    linear_solver.multigrid_setup_seconds += geometric->setup_seconds;
    if (geometric->n_levels() == 1 &&
        geometric->coarse_size() >
          GeometricMultigrid<dim>::largest_jacobi_coarse_size &&
        body.stiffness().is_assembled())
      {
        // No levels (a mesh from a file, non-matching stacked blocks): the
        // "cycle" would be ML on the whole K, rebuilt with the springs at
        // each change of the active sets; ML's own path reuses its
        // hierarchy (block_on_block_3d at d = 58,584: 1.4 s per increment
        // against 19 s).
        pcout << "Geometric multigrid: the mesh has one level; the solves "
                 "take the AMG (Trilinos ML) instead"
              << std::endl;
        geometric.reset();
        return;
      }
    // The Newton systems' springs change the levels' operators: they get
    // a cycle of their own, on the same levels (not with contact pairs:
    // MortarPreconditioner).
    if (model.get_contact().active() && !model.get_contact().has_pairs())
      {
        geometric_with_springs = std::make_unique<GeometricMultigrid<dim>>();
        geometric_with_springs->initialize_from(*geometric);
        linear_solver.multigrid_setup_seconds += geometric_with_springs->setup_seconds;
      }
    linear_solver.set_geometric_multigrid(geometric.get(), geometric_with_springs.get());
    pcout << "Geometric multigrid: " << geometric->n_levels() << " levels, "
          << geometric->coarse_size() << " unknowns on the coarsest" << std::endl;
  }



  template <int dim>
  void
  IncrementSolver<dim>::print_method() const
  {
    if (contact_active)
      pcout << "Solver: " << solver.method->describe() << std::endl
            << "    sigma_T = " << Input::to_text(sigma_T)
            << " (largest singular value of T)" << std::endl;
  }



  template <int dim>
  double
  IncrementSolver<dim>::smallest_eigenvalue_of_K(const Model<dim> &model,
                                                 TimerOutput      &timer)
  {
    if (mu_pi > 0)
      return mu_pi;
    TimerOutput::Scope       scope(timer, "Smallest eigenvalue of K");
    const SmallestEigenvalue eigenvalue =
      compute_smallest_eigenvalue(stiffness(model),
                                  linear_solver,
                                  solver.eigenvalue_tolerance,
                                  solver.lanczos_vectors);
    mu_pi = eigenvalue.value;
    pcout << "    mu_pi = " << Input::scientific(mu_pi, 6)
          << " (smallest eigenvalue of K, PARPACK; Rayleigh quotient "
          << Input::scientific(eigenvalue.rayleigh_quotient, 6) << ")"
          << std::endl
          << "-- mu_pi took " << eigenvalue.n_solves << " solves with K, "
          << eigenvalue.cg_iterations << " CG iterations" << std::endl;
    return mu_pi;
  }



  template <int dim>
  void
  IncrementSolver<dim>::initialize_on_body(const ElasticBody<dim> &body)
  {
    linear_solver.initialize(body.stiffness(),
                             body.rigid_body_modes(),
                             0.,
                             body.volumetric_split());
  }



  template void
  IncrementSolver<2>::initialize(const Model<2> &);
  template void
  IncrementSolver<2>::make_geometric_multigrid(const Model<2> &);
  template void
  IncrementSolver<2>::print_method() const;
  template double
  IncrementSolver<2>::smallest_eigenvalue_of_K(const Model<2> &, TimerOutput &);
  template void
  IncrementSolver<2>::initialize_on_body(const ElasticBody<2> &);
  template void
  IncrementSolver<3>::initialize(const Model<3> &);
  template void
  IncrementSolver<3>::make_geometric_multigrid(const Model<3> &);
  template void
  IncrementSolver<3>::print_method() const;
  template double
  IncrementSolver<3>::smallest_eigenvalue_of_K(const Model<3> &, TimerOutput &);
  template void
  IncrementSolver<3>::initialize_on_body(const ElasticBody<3> &);
} // namespace FrictionalContact
