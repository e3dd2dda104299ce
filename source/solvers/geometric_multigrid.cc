#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/matrix_free/matrix_free.h>
#include <deal.II/matrix_free/tools.h>
#include <deal.II/multigrid/mg_tools.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <frictional_contact/solvers/geometric_multigrid.h>

#include <cmath>

namespace FrictionalContact
{
  template <int dim>
  void
  CoarseAMG<dim>::initialize(const DoFHandler<dim>                &dof_handler,
                             const ElasticityOperator<dim, float> &coarse,
                             const AffineConstraints<double>      &level_constraints)
  {
    const MPI_Comm  comm     = dof_handler.get_communicator();
    const IndexSet &owned    = dof_handler.locally_owned_mg_dofs(0);
    const IndexSet  relevant = DoFTools::extract_locally_relevant_level_dofs(dof_handler, 0);
    TrilinosWrappers::SparsityPattern pattern(owned, owned, relevant, comm);
    MGTools::make_sparsity_pattern(dof_handler, pattern, 0);
    pattern.compress();
    stiffness.reinit(pattern);
    AffineConstraints<float> constraints;
    constraints.copy_from(level_constraints);
    MatrixFreeTools::compute_matrix<dim, 1, 2, dim, float, VectorizedArray<float>>(
      *coarse.get_matrix_free(), constraints, stiffness,
      [&coarse](FEEvaluation<dim, 1, 2, dim, float> &phi) { coarse.integrate_stiffness(phi); });

    // The near null space: the translations, from each owned dof's
    // component.
    translations.assign(dim, std::vector<bool>(owned.n_elements(), false));
    std::vector<types::global_dof_index> indices(dof_handler.get_fe().n_dofs_per_cell());
    for (const auto &cell : dof_handler.cell_iterators_on_level(0))
      if (cell->is_locally_owned_on_level())
        {
          cell->get_mg_dof_indices(indices);
          for (unsigned int i = 0; i < indices.size(); ++i)
            if (owned.is_element(indices[i]))
              translations[dof_handler.get_fe().system_to_component_index(i).first]
                          [owned.index_within_set(indices[i])] = true;
        }
    build(stiffness);
    src_copy.reinit(owned, comm);
    dst_copy.reinit(owned, comm);
  }



  template <int dim>
  void
  CoarseAMG<dim>::initialize_from(const CoarseAMG<dim> &other)
  {
    stiffness.copy_from(other.stiffness);
    translations = other.translations;
    build(stiffness);
    src_copy.reinit(other.src_copy);
    dst_copy.reinit(other.dst_copy);
  }



  template <int dim>
  void
  CoarseAMG<dim>::set_springs(
    const std::vector<typename ElasticityOperator<dim, float>::Spring> &springs,
    const Utilities::MPI::Partitioner                                  &partitioner)
  {
    with_springs.copy_from(stiffness);
    for (const auto &spring : springs)
      for (unsigned int a = 0; a < spring.rows.size(); ++a)
        for (unsigned int b = 0; b < spring.rows.size(); ++b)
          with_springs.add(partitioner.local_to_global(spring.rows[a]),
                           partitioner.local_to_global(spring.rows[b]),
                           spring.values[a * spring.rows.size() + b]);
    with_springs.compress(VectorOperation::add);
    build(with_springs);
  }



  template <int dim>
  void
  CoarseAMG<dim>::build(const TrilinosWrappers::SparseMatrix &of)
  {
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = false;
    data.smoother_sweeps       = 2;
    data.constant_modes        = translations;
    amg.initialize(of, data);
  }



  template <int dim>
  void
  CoarseAMG<dim>::vmult(LevelVector &dst, const LevelVector &src) const
  {
    for (unsigned int i = 0; i < src_copy.locally_owned_size(); ++i)
      src_copy.local_element(i) = src.local_element(i);
    amg.vmult(dst_copy, src_copy);
    for (unsigned int i = 0; i < dst_copy.locally_owned_size(); ++i)
      dst.local_element(i) = dst_copy.local_element(i);
  }



  template <int dim>
  void
  GeometricMultigrid<dim>::initialize(
    const DoFHandler<dim>                             &dof_handler,
    const std::map<types::boundary_id, ComponentMask> &held,
    const LameParameters                              &lame,
    const AffineConstraints<double>                   &constraints,
    const StiffnessOperator                           &K,
    const unsigned int                                 smoother_degree)
  {
    const Timer timer;
    coarse_amg.reset();
    // K's rows of constrained dofs hold only their diagonal: the cycle
    // divides by it there (the right-hand sides of PARPACK's solves are
    // not zero at those dofs).
    constrained_inverse_diagonal.clear();
    const IndexSet &owned_dofs = dof_handler.locally_owned_dofs();
    for (const auto i : owned_dofs)
      if (constraints.is_constrained(i))
        constrained_inverse_diagonal.emplace_back(owned_dofs.index_within_set(i),
                                                  1. / K.diag_element(i));
    const unsigned int n_level = dof_handler.get_triangulation().n_global_levels();

    constrained_dofs = std::make_shared<MGConstrainedDoFs>();
    constrained_dofs->initialize(dof_handler);
    for (const auto &[id, components] : held)
      constrained_dofs->make_zero_boundary_constraints(dof_handler, {id}, components);

    // The operator of each level on its own MatrixFree data, with the
    // level's held dofs as constraints.
    operators.resize(0, n_level - 1);
    const MappingQ1<dim> mapping;
    for (unsigned int level = 0; level < n_level; ++level)
      {
        AffineConstraints<double> level_constraints;
        level_constraints.reinit(
          DoFTools::extract_locally_relevant_level_dofs(dof_handler, level));
        level_constraints.add_lines(constrained_dofs->get_boundary_indices(level));
        level_constraints.close();
        typename MatrixFree<dim, float>::AdditionalData data;
        data.tasks_parallel_scheme = MatrixFree<dim, float>::AdditionalData::none;
        data.mapping_update_flags  = update_gradients | update_JxW_values;
        data.mg_level              = level;
        auto storage               = std::make_shared<MatrixFree<dim, float>>();
        storage->reinit(mapping, dof_handler, level_constraints, QGauss<1>(2), data);
        operators[level].initialize(storage, *constrained_dofs, level);
        operators[level].set_materials(lame);
        operators[level].compute_diagonal();
        if (level == 0 && operators[0].m() > largest_jacobi_coarse_size)
          {
            coarse_amg = std::make_shared<CoarseAMG<dim>>();
            coarse_amg->initialize(dof_handler, operators[0], level_constraints);
          }
      }
    coarse_unknowns = operators[0].m();

    transfer = std::make_shared<MGTransferMatrixFree<dim, float>>();
    transfer->initialize_constraints(*constrained_dofs);
    transfer->build(dof_handler);

    this->dof_handler     = &dof_handler;
    this->smoother_degree = smoother_degree;
    largest_eigenvalues.clear();
    finish_setup();
    setup_seconds = timer.wall_time();
  }



  template <int dim>
  void
  GeometricMultigrid<dim>::initialize_from(const GeometricMultigrid<dim> &other)
  {
    const Timer timer;
    dof_handler                  = other.dof_handler;
    smoother_degree              = other.smoother_degree;
    constrained_dofs             = other.constrained_dofs;
    transfer                     = other.transfer;
    coarse_amg.reset();
    if (other.coarse_amg)
      {
        coarse_amg = std::make_shared<CoarseAMG<dim>>();
        coarse_amg->initialize_from(*other.coarse_amg);
      }
    constrained_inverse_diagonal = other.constrained_inverse_diagonal;
    coarse_unknowns              = other.coarse_unknowns;
    // Copies of the level operators: the same MatrixFree data and K's
    // diagonal; springs give each copy a diagonal of its own. The
    // smoothers estimate their eigenvalues anew (build_cycle()).
    largest_eigenvalues.clear();
    operators.resize(0, other.operators.max_level());
    for (unsigned int level = 0; level <= operators.max_level(); ++level)
      operators[level] = other.operators[level];
    finish_setup();
    setup_seconds = timer.wall_time();
  }



  template <int dim>
  void
  GeometricMultigrid<dim>::finish_setup()
  {
    const unsigned int n_level = operators.max_level() + 1;
    interfaces.resize(0, n_level - 1);
    for (unsigned int level = 0; level < n_level; ++level)
      interfaces[level].initialize(operators[level]);
    level_matrices     = std::make_unique<mg::Matrix<LevelVector>>(operators);
    interface_matrices = std::make_unique<mg::Matrix<LevelVector>>(interfaces);
    level_has_springs.assign(n_level, false);
    active_to_level.clear();
    build_cycle();

    const IndexSet owned    = dof_handler->locally_owned_dofs();
    const IndexSet relevant = DoFTools::extract_locally_relevant_dofs(*dof_handler);
    src_copy.reinit(owned, relevant, dof_handler->get_communicator());
    dst_copy.reinit(owned, relevant, dof_handler->get_communicator());
  }



  template <int dim>
  void
  GeometricMultigrid<dim>::build_cycle()
  {
    // Chebyshev on the upper part of each level's spectrum (1/15 of the
    // largest eigenvalue up), which CG estimates in 10 iterations when the
    // cycle is first made. Springs keep those estimates: with the diagonal
    // they add, the Jacobi-scaled rows of their nodes are nearer the
    // identity, and estimating again at every change of the Newton
    // method's active sets cost a third of its solve.
    const unsigned int n_level = operators.max_level() + 1;
    MGLevelObject<typename Smoother::AdditionalData> smoother_data(0, n_level - 1);
    for (unsigned int level = 0; level < n_level; ++level)
      {
        smoother_data[level].smoothing_range     = 15.;
        smoother_data[level].degree              = smoother_degree;
        smoother_data[level].eig_cg_n_iterations = largest_eigenvalues.empty() ? 10 : 0;
        if (!largest_eigenvalues.empty())
          smoother_data[level].max_eigenvalue = largest_eigenvalues[level];
        smoother_data[level].preconditioner =
          operators[level].get_matrix_diagonal_inverse();
      }
    smoother.initialize(operators, smoother_data);
    if (largest_eigenvalues.empty())
      for (unsigned int level = 0; level < n_level; ++level)
        {
          LevelVector start;
          operators[level].initialize_dof_vector(start);
          start = 1.;
          // The estimate with the safety factor Chebyshev itself applies.
          largest_eigenvalues.push_back(
            1.2 * smoother[level].estimate_eigenvalues(start).max_eigenvalue_estimate);
        }

    coarse_control = std::make_unique<ReductionControl>(10000, 1e-20, 1e-3, false, false);
    coarse_cg      = std::make_unique<SolverCG<LevelVector>>(*coarse_control);
    if (coarse_amg)
      coarse = std::make_unique<
        MGCoarseGridIterativeSolver<LevelVector, SolverCG<LevelVector>, LevelOperator, CoarseAMG<dim>>>(
        *coarse_cg, operators[0], *coarse_amg);
    else
      coarse = std::make_unique<MGCoarseGridIterativeSolver<LevelVector,
                                                            SolverCG<LevelVector>,
                                                            LevelOperator,
                                                            DiagonalMatrix<LevelVector>>>(
        *coarse_cg, operators[0], *operators[0].get_matrix_diagonal_inverse());
    multigrid = std::make_unique<Multigrid<LevelVector>>(
      *level_matrices, *coarse, *transfer, smoother, smoother);
    multigrid->set_edge_matrices(*interface_matrices, *interface_matrices);
    cycle = std::make_unique<PreconditionMG<dim, LevelVector, MGTransferMatrixFree<dim, float>>>(
      *dof_handler, *multigrid, *transfer);
  }



  template <int dim>
  void
  GeometricMultigrid<dim>::map_active_to_level_dofs()
  {
    // For each dof at a vertex of an owned active cell: its dof on the
    // cell's level, then on each coarser level whose parent cell has the
    // same vertex.
    for (const auto &cell : dof_handler->active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int c = 0; c < dim; ++c)
            {
              const types::global_dof_index dof = cell->vertex_dof_index(v, c);
              if (active_to_level.count(dof) > 0)
                continue;
              std::vector<std::pair<unsigned int, types::global_dof_index>> &chain =
                active_to_level[dof];
              typename DoFHandler<dim>::level_cell_iterator on_level(
                &dof_handler->get_triangulation(), cell->level(), cell->index(), dof_handler);
              unsigned int vertex = v;
              while (true)
                {
                  chain.emplace_back(on_level->level(),
                                     on_level->mg_vertex_dof_index(on_level->level(), vertex, c));
                  if (on_level->level() == 0)
                    break;
                  const auto   parent = on_level->parent();
                  unsigned int found  = numbers::invalid_unsigned_int;
                  for (const unsigned int w : parent->vertex_indices())
                    if (parent->vertex_index(w) == on_level->vertex_index(vertex))
                      found = w;
                  if (found == numbers::invalid_unsigned_int)
                    break;
                  on_level = parent;
                  vertex   = found;
                }
            }
  }



  template <int dim>
  void
  GeometricMultigrid<dim>::set_springs(const std::vector<NodalBlock> &springs)
  {
    if (active_to_level.empty())
      map_active_to_level_dofs();
    const unsigned int n_level = operators.max_level() + 1;
    std::vector<std::vector<typename LevelOperator::Spring>> per_level(n_level);
    // A spring goes to the level of its node's active cells and to each
    // coarser level where the node is a vertex, scaled there as the
    // diagonal of K grows with the cells (2^(dim-2) per level).
    for (const NodalBlock &block : springs)
      for (unsigned int depth = 0;; ++depth)
        {
          typename LevelOperator::Spring spring;
          unsigned int                   level = 0;
          bool                           found = true;
          for (const auto dof : block.dofs)
            {
              const auto it = active_to_level.find(dof);
              if (it == active_to_level.end() || it->second.size() <= depth)
                {
                  found = false;
                  break;
                }
              level = it->second[depth].first;
              const auto &partitioner =
                operators[level].get_matrix_free()->get_vector_partitioner();
              if (!partitioner->in_local_range(it->second[depth].second))
                {
                  found = false;
                  break;
                }
              spring.rows.push_back(partitioner->global_to_local(it->second[depth].second));
            }
          if (!found)
            break;
          const double scale = std::pow(2., (dim - 2.) * depth);
          for (const double value : block.values)
            spring.values.push_back(scale * value);
          per_level[level].push_back(std::move(spring));
        }
    for (unsigned int level = 0; level < n_level; ++level)
      {
        const bool has_springs =
          Utilities::MPI::logical_or(!per_level[level].empty(),
                                     dof_handler->get_communicator());
        if (!has_springs && !level_has_springs[level])
          continue;
        if (level == 0 && coarse_amg)
          coarse_amg->set_springs(per_level[0],
                                  *operators[0].get_matrix_free()->get_vector_partitioner());
        operators[level].set_springs(std::move(per_level[level]));
        operators[level].compute_diagonal();
        level_has_springs[level] = has_springs;
      }
    build_cycle();
  }



  template <int dim>
  void
  GeometricMultigrid<dim>::vmult(Vector &dst, const Vector &src) const
  {
    copy_owned_entries(src, src_copy);
    cycle->vmult(dst_copy, src_copy);
    copy_owned_entries(dst_copy, dst);
    double       *values = dst.begin();
    const double *source = src.begin();
    for (const auto &[index, inverse] : constrained_inverse_diagonal)
      values[index] = inverse * source[index];
  }

  template class CoarseAMG<2>;
  template class CoarseAMG<3>;
  template class GeometricMultigrid<2>;
  template class GeometricMultigrid<3>;
} // namespace FrictionalContact
