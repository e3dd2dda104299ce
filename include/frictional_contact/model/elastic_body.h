#pragma once

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <frictional_contact/model/boundary_conditions.h>
#include <frictional_contact/material/material.h>
#include <frictional_contact/model/volumetric_blocks.h>
#include <frictional_contact/solvers/elasticity_operator.h>
#include <frictional_contact/solvers/stiffness_operator.h>

#include <array>
#include <memory>
#include <set>
#include <vector>

namespace FrictionalContact
{
  /// Which supports a reaction sums: all fixed and prescribed boundaries,
  /// or only the prescribed ones (the force that moves them).
  enum class Supports
  {
    all,
    prescribed
  };
  /**
   * The discretised elastic body: Q1 displacement field on a distributed
   * mesh (the standard or the B-bar element, as the material says), its
   * zero-displacement constraints, the stiffness K (assembled, or
   * matrix-free: MatrixFreeStiffness) and the load vector p of the
   * reference load (load factor 1). Also evaluates the support reactions
   * for a given displacement.
   */
  template <int dim>
  class ElasticBody
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    /// @p bodies names the bodies (material ids) for the messages;
    /// @p matrix_free: K is never assembled (MatrixFreeStiffness).
    ElasticBody(const parallel::distributed::Triangulation<dim> &triangulation,
                const Materials<dim>                            &materials,
                const BoundaryConditions<dim>                   &conditions,
                const std::map<std::string, types::material_id> &bodies,
                const bool                                       matrix_free);

    /// Distributes the dofs, builds the constraints and the sparsity pattern
    /// (or, matrix-free, the operator of K).
    void
    setup();

    /// The largest nodal magnitude |u(x_v)| over all vertices, for a
    /// (non-ghosted) vector @p u. Collective.
    double
    largest_nodal_magnitude(const Vector &u) const;

    /// Assembles K (unless matrix-free) and p. Call after setup().
    void
    assemble();

    /**
     * The bodies that the fixed boundaries do not hold against every
     * rigid-body motion (translations and rotations): K is singular on
     * them, and only contact can hold them. Collective.
     */
    std::set<types::material_id>
    bodies_free_to_move() const;

    /// Whether each locally owned dof (by its index in the owned set) is
    /// a dof of a cell of the bodies @p ids.
    std::vector<bool>
    owned_dofs_of(const std::set<types::material_id> &ids) const;

    /**
     * The internal force K u at the unconstrained dofs (zero at the
     * others), for a displacement @p u that may be non-zero on prescribed
     * boundaries: the condensed stiffness matrix alone would miss their
     * coupling to the free dofs.
     */
    void
    internal_force(const Vector &u, Vector &force) const;

    /**
     * The sum of the support reactions (forces the supports exert on the
     * body) for the displacement @p u (with ghost entries) under the load
     * factor @p load_factor: the unconstrained residual K u - p at the
     * constrained dofs, summed per component.
     */
    Tensor<1, dim>
    support_reaction(const Vector &u,
                     const double  load_factor,
                     const Supports supports = Supports::all) const;

    /// The same for bodies of nonlinear laws, from their internal force
    /// @p internal_force (distributed with the hanging-node constraints
    /// only). Collective.
    Tensor<1, dim>
    support_reaction_of(const Vector  &internal_force,
                        const double   load_factor,
                        const Supports supports = Supports::all) const;

    /// Whether a boundary of the body is prescribed (moved, not fixed).
    bool
    has_prescribed_boundaries() const
    {
      return !conditions.prescribed_boundaries.empty();
    }

    /// The assembled K, to be replaced by the tangent of nonlinear laws
    /// (BodyResponse::internal_force()) in place: what refers to K sees the
    /// tangent from then on.
    TrilinosWrappers::SparseMatrix &
    matrix_for_tangent()
    {
      return stiffness_matrix;
    }

    /**
     * The increment of the prescribed displacements from time @p t_old to
     * @p t_new, at the prescribed dofs (and at hanging vertices on their
     * boundaries, from the vertices they hang from), zero elsewhere (the
     * lifting of an increment; the solves then work with homogeneous
     * constraints).
     */
    void
    prescribed_increment(const double t_old,
                         const double t_new,
                         Vector      &increment) const;

    /// The total applied force (tractions and body force) for load factor 1.
    const Tensor<1, dim> &
    total_load() const
    {
      return reference_total_load;
    }

    /**
     * Rigid-body modes (dim(dim+1)/2 of them: translations, then rotations)
     * at the locally owned dofs, for the AMG's near null space.
     */
    std::vector<std::vector<double>>
    rigid_body_modes() const;

    /// The bodies: name -> material id of their cells.
    const std::map<std::string, types::material_id> &
    get_bodies() const
    {
      return bodies;
    }

    /// The law of each body.
    const Materials<dim> &
    get_materials() const
    {
      return materials;
    }

    /// The name of the body whose cells have material id @p id.
    std::string
    body_name(const types::material_id id) const
    {
      for (const auto &[name, body_id] : bodies)
        if (body_id == id)
          return name;
      return std::to_string(id);
    }

    /// Number of displacement dofs that are not fixed (the paper's d).
    types::global_dof_index
    n_free_dofs() const
    {
      return n_free;
    }

    Vector
    make_vector() const
    {
      return Vector(owned_dofs, mpi_communicator);
    }

    Vector
    make_ghosted_vector() const
    {
      return Vector(owned_dofs, relevant_dofs, mpi_communicator);
    }

    const DoFHandler<dim> &
    get_dof_handler() const
    {
      return dof_handler;
    }

    const AffineConstraints<double> &
    get_constraints() const
    {
      return constraints;
    }

    /// The hanging-node constraints alone (a hanging dof in terms of the
    /// dofs it hangs from, whether those are fixed or not).
    const AffineConstraints<double> &
    get_hanging_node_constraints() const
    {
      return hanging_node_constraints;
    }

    const StiffnessOperator &
    stiffness() const
    {
      return *stiffness_operator;
    }

    /// Lame's lambda and mu of each body, from its stress-strain tensor.
    LameParameters
    lame_parameters() const;

    /// Those of the split's reduced stiffness A where a body has a split
    /// (VolumetricBlocks::reduced_lame_parameters()), else of K: what the
    /// geometric multigrid preconditions in the mixed solves.
    LameParameters
    reduced_lame_parameters() const;

    /// K with its volumetric part held apart, for a nearly incompressible
    /// (B-bar) body; empty (null pointers) otherwise.
    VolumetricSplit
    volumetric_split() const
    {
      return volumetric.split();
    }

    const Vector &
    load_vector() const
    {
      return load;
    }

    const IndexSet &
    locally_owned_dofs() const
    {
      return owned_dofs;
    }

    /// The dofs of this rank's cells and their neighbours' (ghosts).
    const IndexSet &
    locally_relevant_dofs() const
    {
      return relevant_dofs;
    }

    MPI_Comm
    get_mpi_communicator() const
    {
      return mpi_communicator;
    }

    /// Whether dof @p i is held by a fixed boundary (not a hanging node).
    bool
    is_fixed(const types::global_dof_index i) const
    {
      return constraints.is_constrained(i) &&
             constraints.get_constraint_entries(i)->empty();
    }

  private:
    /// The components of @p residual summed over the fixed dofs (or
    /// only the prescribed ones).
    Tensor<1, dim>
    sum_at_fixed_dofs(const Vector &residual, const Supports supports) const;

    /**
     * force = sum over the locally owned cells of K_e u_e - load_factor p_e,
     * distributed with @p distribute (all constraints, or only the
     * hanging-node ones). @p u_ghosted must have ghost entries.
     */
    void
    element_forces(const Vector                    &u_ghosted,
                   const double                     load_factor,
                   const AffineConstraints<double> &distribute,
                   Vector                          &force) const;

    /// What assembling one cell needs: the (face) values of Q1 at the
    /// 2 x 2 (x 2) Gauss points, the cell matrix and load, the dof indices.
    struct CellScratch
    {
      explicit CellScratch(const FiniteElement<dim> &fe);

      QGauss<dim>                          quadrature;
      QGauss<dim - 1>                      face_quadrature;
      FEValues<dim>                        fe_values;
      FEFaceValues<dim>                    fe_face_values;
      FullMatrix<double>                   cell_matrix;
      dealii::Vector<double>               cell_load;
      std::vector<types::global_dof_index> dof_indices;
      /// The integrals of div phi_i over the cell, and its volume.
      std::vector<double>                  divergence_integral;
      double                               volume = 0;
    };

    /// The cell matrix (if @p with_matrix) and load of @p cell, into
    /// @p scratch.
    void
    assemble_cell(const typename DoFHandler<dim>::active_cell_iterator &cell,
                  CellScratch &scratch,
                  const bool   with_matrix = true) const;

    /// The cell matrix of the cell @p scratch's FEValues are at (of the
    /// body @p id), and its divergence integrals and volume.
    void
    cell_stiffness(const types::material_id id, CellScratch &scratch) const;

    const Materials<dim>                     &materials;
    const BoundaryConditions<dim>            &conditions;
    std::map<std::string, types::material_id> bodies;
    MPI_Comm                          mpi_communicator;

    FESystem<dim>   fe;
    DoFHandler<dim> dof_handler;
    IndexSet        owned_dofs;
    IndexSet        relevant_dofs;
    /// The locally owned dofs of each displacement component.
    std::array<IndexSet, dim> component_dofs;

    AffineConstraints<double>      constraints;
    /// Only the hanging-node part of constraints (for support reactions
    /// and the candidates' areas).
    AffineConstraints<double>      hanging_node_constraints;
    /// Locally owned dofs of prescribed (not fixed) boundaries.
    IndexSet                       prescribed_dofs;
    const bool                     matrix_free;
    /// Empty when matrix-free.
    TrilinosWrappers::SparseMatrix stiffness_matrix;
    std::unique_ptr<StiffnessOperator> stiffness_operator;
    Vector                         load;
    Tensor<1, dim>                 reference_total_load;
    /// The volumetric split of K (B-bar bodies only).
    VolumetricBlocks<dim>          volumetric;
    types::global_dof_index        n_free = 0;
  };
} // namespace FrictionalContact
