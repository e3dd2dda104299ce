#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>

#include <frictional_contact/base/input.h>
#include <frictional_contact/geometry/interface.h>
#include <frictional_contact/model/body_response.h>
#include <frictional_contact/model/boundary_conditions.h>
#include <frictional_contact/model/contact_operator.h>
#include <frictional_contact/model/elastic_body.h>
#include <frictional_contact/solvers/elasticity_operator.h>
#include <frictional_contact/material/material.h>
#include <frictional_contact/model/mesh_refinement.h>
#include <frictional_contact/model/quadrature_history.h>

#include <functional>
#include <memory>
#include <set>
#include <vector>

namespace FrictionalContact
{
  /**
   * The scene as a parameter file describes it: the mesh of the geometry
   * (refined), the material, the boundary conditions, the elastic body
   * (dofs, K, loads) and the contact candidates facing the obstacle. Owns
   * the subsection "Geometry"; the others are read by the classes named
   * after them. The constructor reads every entry and makes the coarse
   * mesh; setup() refines it (or loads a saved one) and builds the rest.
   */
  template <int dim>
  class Model
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    Model(ParameterHandler &prm, const MPI_Comm comm);

    /**
     * Makes the mesh, by refining the coarse one or, if @p load_mesh is
     * given, by letting it replace the mesh (a checkpoint's); then the dofs,
     * constraints and contact candidates. Throws an InputError if a rank
     * would own no unknowns.
     */
    void
    setup(const std::function<void(parallel::distributed::Triangulation<dim> &)>
            &load_mesh = {});

    /**
     * Adapts the mesh between solves: lets @p mark flag cells (it returns
     * whether it flagged any, on any rank); if it did, refines and coarsens
     * them, makes the dofs, constraints and candidates of the new mesh (the
     * obstacle where it was) and carries the nodal @p fields (locally owned
     * vectors of the old mesh) over, by interpolation. Call assemble()
     * next. Returns whether the mesh changed.
     */
    bool
    adapt(const std::function<bool(parallel::distributed::Triangulation<dim> &)>
                                                 &mark,
          const std::vector<TrilinosWrappers::MPI::Vector *> &fields);

    /// Assembles K and the loads; throws an InputError if the supports
    /// allow a rigid-body motion of a body that no contact faces.
    void
    assemble();

    /// Whether some body's law is not linear (plasticity): its increments
    /// take Newton's method on the internal force, with a tangent made at
    /// each step.
    bool
    nonlinear() const
    {
      return !materials->all_linear();
    }

    /// The bodies' response (internal force, tangent, stress) to a
    /// displacement, from the committed history.
    const BodyResponse<dim> &
    get_response() const
    {
      return *response;
    }

    /**
     * K_T(u) into the body's matrix (what refers to K sees it), and
     * f_int(u) into @p force (zero at the held dofs), for @p u_ghosted.
     * Returns the points that flow plastically. Collective.
     */
    types::global_dof_index
    update_tangent(const TrilinosWrappers::MPI::Vector &u_ghosted,
                   TrilinosWrappers::MPI::Vector       &force);

    /// Commits the history of the displacement @p u of an accepted
    /// increment. Collective.
    void
    commit(const TrilinosWrappers::MPI::Vector &u);

    /// The quadrature history, for checkpoints.
    QuadratureHistory<dim> &
    get_history()
    {
      return *history;
    }

    /// Takes the history of a loaded checkpoint from the mesh (after its
    /// vectors). Collective.
    void
    load_history()
    {
      history->unpack(*triangulation);
    }

    /// The sum of the support reactions for the displacement @p u_ghosted
    /// (ElasticBody::support_reaction(), from the laws' internal force when
    /// they are not linear). Collective.
    Tensor<1, dim>
    support_reaction(const TrilinosWrappers::MPI::Vector &u_ghosted,
                     const double                         load_factor,
                     const Supports supports = Supports::all) const;

    /// The bodies (material ids) that only contact holds against rigid-body
    /// motion: K is singular on them (after assemble()).
    const std::set<types::material_id> &
    bodies_held_by_contact_alone() const
    {
      return held_by_contact_alone;
    }

    /// The header lines of a run: scene, mesh, contact.
    void
    print_summary(const ConditionalOStream &out) const;

    const parallel::distributed::Triangulation<dim> &
    mesh() const
    {
      return *triangulation;
    }

    MPI_Comm
    get_mpi_communicator() const
    {
      return triangulation->get_communicator();
    }

    const ElasticBody<dim> &
    get_body() const
    {
      return *body;
    }

    const ContactOperator<dim> &
    get_contact() const
    {
      return *contact;
    }

    /// The contact operator, to move the obstacle.
    ContactOperator<dim> &
    get_contact()
    {
      return *contact;
    }

    const Materials<dim> &
    get_materials() const
    {
      return *materials;
    }

    /// The boundary components held in the solves: those of the fixed
    /// and of the prescribed boundaries (whose increments are lifted).
    std::map<types::boundary_id, ComponentMask>
    held_boundaries() const;

    /// The bodies of the scene: name -> material id of their cells.
    const std::map<std::string, types::material_id> &
    get_bodies() const
    {
      return bodies;
    }

  private:
    /// The dofs, constraints and contact candidates of the current mesh
    /// (its hanging vertices conformed first).
    void
    make_dofs_and_candidates();

    /// The triangulation (with the levels of the multigrid if
    /// <Linear solver/Preconditioner> asks for it) and the geometry's coarse
    /// mesh in it, its cells of the one body if there is one body.
    void
    make_coarse_mesh(ParameterHandler &prm, const MPI_Comm comm);

    /**
     * With <Linear solver/Preconditioner> = auto, a mesh (after its global
     * refinements) that this machine holds with K matrix-free and the
     * geometric multigrid but not with K assembled and ML: sets those two
     * entries of @p prm, so that every class reading them later takes that
     * path, keeps the line that says so for print_summary() and returns
     * true. Not for B-bar bodies and contact pairs (they need the
     * assembled K).
     */
    bool
    choose_matrix_free_for_memory(ParameterHandler &prm);

    // Made one after the other in the constructor: each needs the ones
    // before it (the boundary names need the coarse mesh), except that the
    // bodies come before the coarse mesh (its cells take their material
    // id) and the contact operator before the body (the choice of the
    // solver path asks whether there are contact pairs; declared after
    // the body, so that it is destroyed first).
    std::unique_ptr<Geometry::Interface<dim>>                  geometry;
    std::unique_ptr<MeshRefinement<dim>>                       refinement;
    std::unique_ptr<parallel::distributed::Triangulation<dim>> triangulation;
    BoundaryNames                                              boundary_names;
    std::map<std::string, types::material_id>                  bodies;
    std::unique_ptr<Materials<dim>>                            materials;
    std::unique_ptr<QuadratureHistory<dim>>                    history;
    std::unique_ptr<BoundaryConditions<dim>> boundary_conditions;
    std::unique_ptr<ElasticBody<dim>>        body;
    std::unique_ptr<BodyResponse<dim>>       response;
    std::unique_ptr<ContactOperator<dim>>    contact;
    /// See bodies_held_by_contact_alone().
    std::set<types::material_id> held_by_contact_alone;
    /// What <Linear solver/Preconditioner> = auto chose for the memory, if
    /// it chose (choose_matrix_free_for_memory()).
    std::string automatic_choice;
  };
} // namespace FrictionalContact
