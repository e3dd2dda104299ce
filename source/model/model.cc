#include <deal.II/base/mpi.h>
#include <deal.II/distributed/solution_transfer.h>

#include <frictional_contact/base/plugins.h>
#include <frictional_contact/model/model.h>

#include <ostream>
#include <set>

namespace FrictionalContact
{
  namespace
  {
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
  Model<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    PluginRegistry<Geometry::Interface<dim>>::declare_parameters(
      prm, "box", "The shape of the elastic body and its boundary names.");
    prm.leave_subsection();
    prm.enter_subsection("Mesh refinement");
    MeshRefinement<dim>::declare_parameters(prm);
    prm.leave_subsection();

    Materials<dim>::declare_parameters(prm);
    BoundaryConditions<dim>::declare_parameters(prm);
    ContactOperator<dim>::declare_parameters(prm);
  }



  namespace
  {
    /// Whether <Linear solver/Preconditioner> asks for geometric multigrid:
    /// then the mesh keeps its levels on every rank (p4est's multigrid
    /// hierarchy) and refines with at most one level between neighbours
    /// at a vertex, as local smoothing needs. Other runs keep the mesh
    /// without either.
    bool
    wants_mesh_levels(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      const bool levels = prm.get("Preconditioner") == "geometric multigrid";
      prm.leave_subsection();
      return levels;
    }

    /// <Linear solver/Matrix-free stiffness>, which needs the geometric
    /// multigrid (ML and the Cholesky factor need K's entries).
    bool
    wants_matrix_free_stiffness(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      const bool matrix_free = prm.get_bool("Matrix-free stiffness");
      const std::string preconditioner = prm.get("Preconditioner");
      prm.leave_subsection();
      if (matrix_free && preconditioner != "geometric multigrid")
        throw InputError("<Linear solver/Matrix-free stiffness> is true but "
                         "<Linear solver/Preconditioner> is '" + preconditioner +
                         "': set the preconditioner to geometric multigrid "
                         "(the others need the assembled K)");
      return matrix_free;
    }
  } // namespace



  template <int dim>
  Model<dim>::Model(ParameterHandler &prm, const MPI_Comm comm)
  {
    prm.enter_subsection("Geometry");
    geometry = PluginRegistry<Geometry::Interface<dim>>::create(prm);
    prm.leave_subsection();
    prm.enter_subsection("Mesh refinement");
    refinement = std::make_unique<MeshRefinement<dim>>(prm);
    prm.leave_subsection();

    bodies = geometry->body_names();
    make_coarse_mesh(prm, comm);
    boundary_names = BoundaryNames(geometry->boundary_names(),
                                   boundary_ids_in(*triangulation));
    materials      = std::make_unique<Materials<dim>>(prm, bodies);
    history = std::make_unique<QuadratureHistory<dim>>(*materials, QGauss<dim>(2));
    boundary_conditions =
      std::make_unique<BoundaryConditions<dim>>(prm, boundary_names);
    contact = std::make_unique<ContactOperator<dim>>(prm, boundary_names);
    if (choose_matrix_free_for_memory(prm))
      // Again, with the levels the multigrid needs.
      make_coarse_mesh(prm, comm);
    const bool matrix_free = wants_matrix_free_stiffness(prm);
    refinement->set_matrix_free_stiffness(matrix_free);
    body = std::make_unique<ElasticBody<dim>>(*triangulation,
                                              *materials,
                                              *boundary_conditions,
                                              bodies,
                                              matrix_free);
    response = std::make_unique<BodyResponse<dim>>(*body, *materials, *history);
    if (nonlinear() && (matrix_free || wants_mesh_levels(prm)))
      throw InputError("<Linear solver/Preconditioner> = geometric multigrid "
                       "(and Matrix-free stiffness) does not serve nonlinear "
                       "bodies (" + materials->describe_nonlinearity() +
                       ") yet: set the preconditioner to auto or AMG");
    if (matrix_free && materials->any_mean_dilatation())
      throw InputError("<Linear solver/Matrix-free stiffness> does not serve "
                       "B-bar bodies (nearly incompressible materials) yet: "
                       "set it to false");
    if (matrix_free && contact->has_pairs())
      throw InputError("<Linear solver/Matrix-free stiffness> does not serve "
                       "contact pairs (<Contact/Pairs>) yet: set it to false");
    if (materials->axisymmetric() && (matrix_free || wants_mesh_levels(prm)))
      throw InputError("<Linear solver/Preconditioner> = geometric multigrid "
                       "(and Matrix-free stiffness) does not serve axisymmetric "
                       "bodies (<Material/Two-dimensional model> = axisymmetric) "
                       "yet: set the preconditioner to auto or AMG");
  }



  template <int dim>
  void
  Model<dim>::make_coarse_mesh(ParameterHandler &prm, const MPI_Comm comm)
  {
    const bool levels = wants_mesh_levels(prm);
    triangulation     = std::make_unique<parallel::distributed::Triangulation<dim>>(
      comm,
      levels ? Triangulation<dim>::limit_level_difference_at_vertices :
                   Triangulation<dim>::none,
      levels ? parallel::distributed::Triangulation<dim>::construct_multigrid_hierarchy :
                   parallel::distributed::Triangulation<dim>::default_setting);
    geometry->create_coarse_mesh(*triangulation);
    if (bodies.size() == 1)
      for (const auto &cell : triangulation->cell_iterators_on_level(0))
        cell->set_material_id(bodies.begin()->second);
  }



  template <int dim>
  bool
  Model<dim>::choose_matrix_free_for_memory(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    const bool automatic = prm.get("Preconditioner") == "auto" &&
                           !prm.get_bool("Matrix-free stiffness");
    prm.leave_subsection();
    // B-bar bodies, contact pairs, nonlinear laws and axisymmetric bodies
    // need the assembled K.
    if (!automatic || materials->any_mean_dilatation() || contact->has_pairs() ||
        nonlinear() || materials->axisymmetric())
      return false;
    const double n_cells = refinement->cells_after_global_refinement(
      *triangulation, geometry->n_built_in_refinements());
    const double budget = refinement->memory_budget(get_mpi_communicator());
    if (!MeshRefinement<dim>::fits_only_matrix_free(n_cells, budget))
      return false;
    prm.enter_subsection("Linear solver");
    prm.set("Preconditioner", "geometric multigrid");
    prm.set("Matrix-free stiffness", "true");
    prm.leave_subsection();
    automatic_choice =
      "Linear solver: auto takes the geometric multigrid with K matrix-free: "
      "the mesh of " + std::to_string(static_cast<long long>(n_cells)) +
      " cells needs about " +
      MeshRefinement<dim>::describe_bytes(
        MeshRefinement<dim>::bytes_needed(n_cells, false)) +
      " with K assembled and ML, more than " +
      refinement->describe_budget(budget) + ", and " +
      MeshRefinement<dim>::describe_bytes(
        MeshRefinement<dim>::bytes_needed(n_cells, true)) +
      " without K";
    return true;
  }



  template <int dim>
  void
  Model<dim>::setup(
    const std::function<void(parallel::distributed::Triangulation<dim> &)>
      &load_mesh)
  {
    if (load_mesh)
      load_mesh(*triangulation);
    else
      refinement->refine(*triangulation, geometry->n_built_in_refinements());
    make_dofs_and_candidates();
    // A checkpoint's history comes with its vectors (Simulator).
    if (!load_mesh)
      history->reset(*triangulation);
  }



  template <int dim>
  bool
  Model<dim>::adapt(
    const std::function<bool(parallel::distributed::Triangulation<dim> &)> &mark,
    const std::vector<TrilinosWrappers::MPI::Vector *> &fields)
  {
    if (!mark(*triangulation))
      return false;
    using Vector = TrilinosWrappers::MPI::Vector;
    std::vector<Vector>         ghosted(fields.size());
    std::vector<const Vector *> old_fields;
    for (unsigned int i = 0; i < fields.size(); ++i)
      {
        ghosted[i] = body->make_ghosted_vector();
        ghosted[i] = *fields[i];
        old_fields.push_back(&ghosted[i]);
      }
    parallel::distributed::SolutionTransfer<dim, Vector> transfer(
      body->get_dof_handler());
    triangulation->prepare_coarsening_and_refinement();
    transfer.prepare_for_coarsening_and_refinement(old_fields);
    history->attach(*triangulation);
    const Tensor<1, dim> obstacle = contact->obstacle_position();
    MeshRefinement<dim>::restore_hanging_vertices(*triangulation);
    triangulation->execute_coarsening_and_refinement();

    make_dofs_and_candidates();
    if (contact->active())
      contact->move_obstacle(obstacle);
    std::vector<Vector *> new_fields(fields);
    for (Vector *field : new_fields)
      *field = body->make_vector();
    transfer.interpolate(new_fields);
    history->unpack(*triangulation);
    // Only the hanging nodes: the full constraints also hold the prescribed
    // dofs, at zero, while a field such as u has their values there.
    for (Vector *field : fields)
      body->get_hanging_node_constraints().distribute(*field);
    return true;
  }



  template <int dim>
  void
  Model<dim>::make_dofs_and_candidates()
  {
    MeshRefinement<dim>::conform_hanging_vertices(*triangulation);
    body->setup();
    // Every rank must own unknowns: the solvers' collective steps
    // (PARPACK, AMG set-up) do not work with an empty share.
    const MPI_Comm                comm         = get_mpi_communicator();
    const types::global_dof_index fewest_owned = Utilities::MPI::min(
      body->get_dof_handler().n_locally_owned_dofs(), comm);
    if (fewest_owned == 0)
      throw InputError(
        "the mesh has " + std::to_string(triangulation->n_global_active_cells()) +
        " cells, too few for " +
        std::to_string(Utilities::MPI::n_mpi_processes(comm)) +
        " MPI ranks (a rank would own no unknowns): run on fewer ranks, or "
        "use a finer mesh (repetitions, <Mesh refinement/Global refinements>)");
    if (contact->active())
      contact->setup(*body, boundary_names);
  }



  template <int dim>
  void
  Model<dim>::assemble()
  {
    body->assemble();
    response->new_mesh();
    held_by_contact_alone.clear();
    const std::map<std::string, types::material_id> &all = bodies;
    for (const types::material_id id : body->bodies_free_to_move())
      {
        if (contact->active() && contact->bodies_facing_contact().count(id) > 0)
          {
            held_by_contact_alone.insert(id);
            continue;
          }
        const std::string name = body->body_name(id);
        throw InputError(
          "<Boundary conditions/Fixed boundaries> does not hold " +
          (all.size() == 1 ? std::string("the body") : "the body '" + name + "'") +
          " against rigid-body motion (translation or rotation), and no "
          "contact (<Contact/Contact boundaries> or <Contact/Pairs>) faces it "
          "to hold it: fix or prescribe more boundaries or components, e.g. "
          "'set Fixed boundaries = " +
          (all.size() == 1 ? std::string("left") : name + " left") + "'");
      }
  }



  template <int dim>
  types::global_dof_index
  Model<dim>::update_tangent(const TrilinosWrappers::MPI::Vector &u_ghosted,
                             TrilinosWrappers::MPI::Vector       &force)
  {
    return response->update_tangent(u_ghosted,
                                    body->get_constraints(),
                                    force,
                                    body->matrix_for_tangent());
  }



  template <int dim>
  void
  Model<dim>::commit(const TrilinosWrappers::MPI::Vector &u)
  {
    if (!history->active())
      return;
    TrilinosWrappers::MPI::Vector u_ghosted = body->make_ghosted_vector();
    u_ghosted                               = u;
    response->commit(u_ghosted);
  }



  template <int dim>
  Tensor<1, dim>
  Model<dim>::support_reaction(const TrilinosWrappers::MPI::Vector &u_ghosted,
                               const double                         load_factor,
                               const Supports                       supports) const
  {
    if (!nonlinear())
      return body->support_reaction(u_ghosted, load_factor, supports);
    TrilinosWrappers::MPI::Vector force = body->make_vector();
    response->internal_force(u_ghosted, body->get_hanging_node_constraints(), force, nullptr);
    return body->support_reaction_of(force, load_factor, supports);
  }



  template <int dim>
  void
  Model<dim>::print_summary(const ConditionalOStream &out) const
  {
    out << "Scene: " << dim << "D, " << materials->describe() << std::endl;
    for (const std::string &warning : materials->locking_warnings())
      out << warning << std::endl;
    for (const std::string &note : boundary_conditions->overridden)
      out << "Note: " << note << std::endl;
    if (!automatic_choice.empty())
      out << automatic_choice << std::endl;
    out << "Mesh: " << triangulation->n_global_active_cells() << " cells; d = "
        << body->n_free_dofs() << " free displacement dofs of "
        << body->get_dof_handler().n_dofs() << std::endl;
    if (contact->active())
      {
        const std::size_t bytes = Utilities::MPI::sum(
          contact->memory_consumption(), get_mpi_communicator());
        out << "Contact: " << contact->describe_friction(boundary_names)
            << ", c = " << contact->n_candidates() << " candidates on "
            << contact->describe_boundaries(boundary_names) << "; " << bytes
            << " bytes of contact data" << std::endl;
      }
    else
      out << "Contact: none (one linear elastic solve)" << std::endl;
  }

  template <int dim>
  std::map<types::boundary_id, ComponentMask>
  Model<dim>::held_boundaries() const
  {
    std::map<types::boundary_id, std::vector<bool>> held;
    for (const auto *list : {&boundary_conditions->fixed_boundaries,
                             &boundary_conditions->prescribed_boundaries})
      for (const auto &boundary : *list)
        {
          std::vector<bool> &mask = held[boundary.id];
          mask.resize(dim, false);
          for (unsigned int c = 0; c < dim; ++c)
            mask[c] = mask[c] || boundary.components[c];
        }
    std::map<types::boundary_id, ComponentMask> result;
    for (const auto &[id, mask] : held)
      result[id] = ComponentMask(mask);
    return result;
  }



  template class Model<2>;
  template class Model<3>;
} // namespace FrictionalContact
