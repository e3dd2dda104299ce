#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/multigrid/mg_coarse.h>
#include <deal.II/multigrid/mg_constrained_dofs.h>
#include <deal.II/multigrid/mg_matrix.h>
#include <deal.II/multigrid/mg_smoother.h>
#include <deal.II/multigrid/mg_transfer_matrix_free.h>
#include <deal.II/multigrid/multigrid.h>

#include <frictional_contact/solvers/elasticity_operator.h>
#include <frictional_contact/solvers/spring_preconditioner.h>
#include <frictional_contact/solvers/stiffness_operator.h>

#include <unordered_map>

#include <map>
#include <memory>

namespace FrictionalContact
{
  /**
   * Trilinos ML on the assembled matrix of the coarsest level (with the
   * springs that level has), as the preconditioner of the coarse CG on
   * single-precision level vectors (converted to double at its boundary).
   * Owns the level's K, its matrix with springs, the AMG, the near null
   * space and two work vectors.
   */
  template <int dim>
  class CoarseAMG : public Subscriptor
  {
  public:
    using LevelVector = LinearAlgebra::distributed::Vector<float>;

    /// Assembles @p coarse (the level-0 operator) and builds the AMG with
    /// the dim translations as near null space. Collective.
    void
    initialize(const DoFHandler<dim>                &dof_handler,
               const ElasticityOperator<dim, float> &coarse,
               const AffineConstraints<double>      &level_constraints);

    /// The same level's K as @p other, without springs. Collective.
    void
    initialize_from(const CoarseAMG<dim> &other);

    /// The AMG of K + @p springs (local indices of the level's vectors,
    /// numbered by @p partitioner) from now on. Collective.
    void
    set_springs(const std::vector<typename ElasticityOperator<dim, float>::Spring> &springs,
                const Utilities::MPI::Partitioner                                  &partitioner);

    void
    vmult(LevelVector &dst, const LevelVector &src) const;

  private:
    /// Builds the AMG of @p of.
    void
    build(const TrilinosWrappers::SparseMatrix &of);

    TrilinosWrappers::SparseMatrix                     stiffness, with_springs;
    std::vector<std::vector<bool>>                     translations;
    TrilinosWrappers::PreconditionAMG                  amg;
    mutable LinearAlgebra::distributed::Vector<double> src_copy, dst_copy;
  };



  /**
   * A geometric multigrid V-cycle for the stiffness K on the levels of the
   * p4est mesh (local smoothing, as in step-37): on each level the
   * matrix-free ElasticityOperator in single precision, Chebyshev smoothing
   * with its inverse diagonal, deal.II's matrix-free transfer
   * between levels, and on the coarsest level a conjugate gradient solve
   * to a relative 1e-3, preconditioned by the inverse diagonal or, above
   * largest_jacobi_coarse_size unknowns, by Trilinos ML on the level's
   * assembled matrix (CoarseAMG). Applied to Trilinos vectors, as the
   * preconditioner of CG with K (assembled or matrix-free); at the
   * constrained dofs (hanging, held), whose rows of K hold only their
   * diagonal, it divides by that diagonal. Owns the level operators, the
   * transfer, the smoother and the cycle.
   */
  template <int dim>
  class GeometricMultigrid : public SpringPreconditioner
  {
  public:
    using Vector        = TrilinosWrappers::MPI::Vector;
    using LevelVector   = LinearAlgebra::distributed::Vector<float>;
    using LevelOperator = ElasticityOperator<dim, float>;

    /**
     * Builds the levels of @p dof_handler (whose triangulation was made
     * with its multigrid hierarchy, and whose level dofs are distributed).
     * @p held: the boundary components held at zero in the solves (fixed
     * and prescribed boundaries); @p constraints: those of the active mesh,
     * @p K the stiffness (for its diagonal at the constrained dofs); @p smoother_degree the Chebyshev degree.
     * Collective.
     */
    void
    initialize(const DoFHandler<dim>                               &dof_handler,
               const std::map<types::boundary_id, ComponentMask>   &held,
               const LameParameters                                &lame,
               const AffineConstraints<double>                     &constraints,
               const StiffnessOperator                             &K,
               const unsigned int                                   smoother_degree);

    /**
     * A second cycle on the levels of @p other (which must outlive this
     * one): the same MatrixFree data, constraints and transfer, copies of
     * its level operators, so that springs set here leave @p other as it
     * is. Collective.
     */
    void
    initialize_from(const GeometricMultigrid<dim> &other);

    bool
    initialized() const override
    {
      return cycle != nullptr;
    }

    /**
     * The cycle for K + the sum of @p springs from now on: each spring goes
     * to the level of the active cells at its node (the finest level of a
     * uniformly refined mesh), where it enters the operator, its diagonal
     * and so the smoother, and to each coarser level where its node is a
     * vertex, scaled by 2^(dim-2) per level as K's diagonal grows. A
     * spring on dofs another rank owns on a level is left out there (it
     * only weakens the preconditioner). Collective.
     */
    void
    set_springs(const std::vector<NodalBlock> &springs) override;

    /// dst = one V-cycle applied to src.
    void
    vmult(Vector &dst, const Vector &src) const override;

    /// Number of levels, and the unknowns of the coarsest one.
    unsigned int
    n_levels() const
    {
      return operators.max_level() + 1;
    }

    types::global_dof_index
    coarse_size() const
    {
      return coarse_unknowns;
    }

    /// Seconds initialize() took.
    double setup_seconds = 0;

    /// Coarsest levels up to this many unknowns take the inverse diagonal
    /// as the coarse CG's preconditioner, larger ones CoarseAMG.
    static constexpr types::global_dof_index largest_jacobi_coarse_size = 1000;

  private:
    using Smoother = PreconditionChebyshev<LevelOperator, LevelVector>;

    /// The interface matrices, the cycle and the vectors from the level
    /// operators (by both initialize functions).
    void
    finish_setup();

    /// (Re)makes the smoothers, the coarse solver and the cycle from the
    /// level operators and their diagonals.
    void
    build_cycle();

    /// Fills active_to_level (for springs).
    void
    map_active_to_level_dofs();

    const DoFHandler<dim>                                            *dof_handler = nullptr;
    unsigned int                                                      smoother_degree = 2;
    /// For each locally owned active dof at a vertex: its (level, level
    /// dof) on the level of its cells and on each coarser level that has
    /// the vertex.
    std::unordered_map<types::global_dof_index,
                       std::vector<std::pair<unsigned int, types::global_dof_index>>>
      active_to_level;
    /// The levels that have springs now.
    std::vector<bool>                                                 level_has_springs;
    /// The largest eigenvalue of each level's Jacobi-scaled operator
    /// without springs (1.2 times CG's estimate), for the smoothers.
    std::vector<double>                                               largest_eigenvalues;

    /// Shared by the cycles made with initialize_from().
    std::shared_ptr<MGConstrainedDoFs>                                constrained_dofs;
    MGLevelObject<LevelOperator>                                      operators;
    MGLevelObject<MatrixFreeOperators::MGInterfaceOperator<LevelOperator>> interfaces;
    std::shared_ptr<MGTransferMatrixFree<dim, float>>                 transfer;
    mg::SmootherRelaxation<Smoother, LevelVector>                     smoother;
    std::unique_ptr<SolverControl>                                    coarse_control;
    std::unique_ptr<SolverCG<LevelVector>>                            coarse_cg;
    /// Each cycle's own (the springs differ); null for a small coarsest
    /// level.
    std::shared_ptr<CoarseAMG<dim>>                                   coarse_amg;
    std::unique_ptr<MGCoarseGridBase<LevelVector>>                    coarse;
    std::unique_ptr<mg::Matrix<LevelVector>>                          level_matrices, interface_matrices;
    std::unique_ptr<Multigrid<LevelVector>>                           multigrid;
    std::unique_ptr<PreconditionMG<dim, LevelVector, MGTransferMatrixFree<dim, float>>>
                                                                      cycle;
    /// (local index, 1 / K_ii) of each locally owned constrained dof.
    std::vector<std::pair<unsigned int, double>>                      constrained_inverse_diagonal;
    mutable LinearAlgebra::distributed::Vector<double>                src_copy, dst_copy;
    types::global_dof_index                                           coarse_unknowns = 0;
  };
} // namespace FrictionalContact
