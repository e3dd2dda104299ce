#include <deal.II/base/mpi.h>

#include <frictional_contact/model/body_response.h>
#include <frictional_contact/model/corner_jacobians.h>

#include <cmath>
#include <stdexcept>

namespace FrictionalContact
{
  // The cell kernels (the strain, stress and tangent of one cell) are in
  // body_response_cell.cc.


  template <int dim>
  BodyResponse<dim>::BodyResponse(const ElasticBody<dim> &body,
                                  const Materials<dim>   &materials,
                                  QuadratureHistory<dim> &history)
    : body(body)
    , materials(materials)
    , history(history)
  {}



  template <int dim>
  BodyResponse<dim>::CellScratch::CellScratch(const FiniteElement<dim> &fe)
    : gauss(2)
    , gauss_values(fe.base_element(0),
                   gauss,
                   update_values | update_gradients | update_quadrature_points |
                     update_JxW_values)
    , lobatto_values(fe.base_element(0),
                     QGaussLobatto<dim>(3),
                     update_values | update_gradients | update_quadrature_points |
                       update_JxW_values)
    , dof(GeometryInfo<dim>::vertices_per_cell)
    , u(fe.n_dofs_per_cell())
    , dof_indices(fe.n_dofs_per_cell())
    , own_JxW(lobatto_values.n_quadrature_points)
    , own_gradients(lobatto_values.n_quadrature_points * GeometryInfo<dim>::vertices_per_cell)
    , mean_divergence(fe.n_dofs_per_cell())
    , responses(lobatto_values.n_quadrature_points)
    , strain(lobatto_values.n_quadrature_points)
    , radius(lobatto_values.n_quadrature_points)
    , values(lobatto_values.n_quadrature_points * GeometryInfo<dim>::vertices_per_cell)
    , revolved_deformation(lobatto_values.n_quadrature_points)
    , revolved_responses(lobatto_values.n_quadrature_points)
    , deformation_gradient(lobatto_values.n_quadrature_points)
    , jacobian(lobatto_values.n_quadrature_points, 1.)
    , matrix(fe.n_dofs_per_cell(), fe.n_dofs_per_cell())
    , force(fe.n_dofs_per_cell())
  {
    for (unsigned int a = 0; a < dof.size(); ++a)
      for (unsigned int c = 0; c < dim; ++c)
        dof[a][c] = fe.component_to_system_index(c, a);
  }



  template <int dim>
  typename BodyResponse<dim>::CellScratch &
  BodyResponse<dim>::fresh_scratch() const
  {
    // The body's element lives as long as the body, and this with it.
    if (!scratch)
      scratch = std::make_unique<CellScratch>(body.get_dof_handler().get_fe());
    scratch->smallest_jacobian = PlacedMinimum<dim>();
    return *scratch;
  }



  template <int dim>
  void
  BodyResponse<dim>::evaluate_cell(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const Vector                                         &u_ghosted,
    const bool                                            with_tangent,
    CellScratch                                          &scratch,
    double                                               *new_history) const
  {
    if constexpr (dim == 2)
      if (materials.axisymmetric())
        return evaluate_revolved_cell(cell, u_ghosted, with_tangent, scratch, new_history);
    const unsigned int        n_vertices = scratch.dof.size();
    const MaterialModel<dim> &law        = materials.of(cell->material_id());
    scratch.corner_points                = law.elastic().corner_points;
    if (reference.kept())
      {
        const unsigned int c = cell->active_cell_index();
        scratch.n_points     = reference.n_points(c);
        scratch.JxW          = reference.JxW(c);
        scratch.gradients    = reference.gradients(c);
        if (scratch.n_points == 0)
          throw std::logic_error("BodyResponse: no reference gradients for a cell "
                                 "this rank owns; new_mesh() must follow every "
                                 "change of the mesh");
      }
    else
      {
        FEValues<dim> &fe_values = scratch.fe_values();
        fe_values.reinit(typename Triangulation<dim>::cell_iterator(cell));
        scratch.n_points = fe_values.n_quadrature_points;
        ReferenceGradients<dim>::copy(fe_values,
                                      scratch.own_JxW.data(),
                                      scratch.own_gradients.data());
        scratch.JxW       = scratch.own_JxW.data();
        scratch.gradients = scratch.own_gradients.data();
      }
    cell->get_dof_values(u_ghosted, scratch.u);
    scratch.finite_strain = law.elastic().finite_strain;

    std::fill(scratch.mean_divergence.begin(), scratch.mean_divergence.end(), 0.);
    double volume = 0, mean_dilatation = 0, mean_volume_ratio = 0;
    std::vector<SymmetricTensor<2, dim>> &strain = scratch.strain;
    for (unsigned int q = 0; q < scratch.n_points; ++q)
      {
        const double JxW = scratch.JxW[q];
        volume += JxW;
        Tensor<2, dim> gradient;
        const Tensor<1, dim> *G = scratch.gradients_at(q);
        for (unsigned int a = 0; a < n_vertices; ++a)
          {
            const Tensor<1, dim> &g = G[a];
            for (unsigned int c = 0; c < dim; ++c)
              {
                gradient[c] += scratch.u(scratch.dof[a][c]) * g;
                scratch.mean_divergence[scratch.dof[a][c]] += g[c] * JxW;
              }
          }
        if (scratch.finite_strain)
          {
            // E = (F^T F - I)/2 = sym(H) + H^T H / 2.
            scratch.deformation_gradient[q] = unit_symmetric_tensor<dim>() + gradient;
            strain[q] = symmetrize(gradient) +
                        0.5 * symmetrize(transpose(gradient) * gradient);
            const double jacobian = scratch.jacobian[q] =
              determinant(scratch.deformation_gradient[q]);
            // (The test spares computing the centre at every point.)
            if (jacobian < scratch.smallest_jacobian.value)
              scratch.smallest_jacobian.keep(jacobian, cell->center());
          }
        else
          {
            strain[q]           = symmetrize(gradient);
            scratch.jacobian[q] = 1.;
          }
        mean_dilatation += trace(strain[q]) * JxW;
        mean_volume_ratio += scratch.jacobian[q] * JxW;
      }
    if (scratch.finite_strain && !scratch.corner_points)
      keep_corner_jacobian(cell, scratch);
    for (double &d : scratch.mean_divergence)
      d /= volume;
    mean_dilatation /= volume;
    mean_volume_ratio /= volume;
    scratch.volume_ratio = law.volume_ratio();
    using VolumeRatio    = typename MaterialModel<dim>::VolumeRatio;

    const bool          b_bar     = law.elastic().mean_dilatation;
    const unsigned int  n_history = law.n_history_values();
    const double       *committed = history.values(cell);
    for (unsigned int q = 0; q < scratch.n_points; ++q)
      if (!(scratch.jacobian[q] > 0))
        // Inverted: no stress (refuse_inverted_cells() stops the solve).
        scratch.responses[q] = MaterialResponse<dim>();
      else
        law.evaluate(strain[q],
                   scratch.volume_ratio == VolumeRatio::cell_mean ? mean_volume_ratio :
                   scratch.volume_ratio == VolumeRatio::point     ? scratch.jacobian[q] :
                   b_bar                                          ? mean_dilatation :
                                                                    trace(strain[q]),
                   committed == nullptr ? nullptr : committed + q * n_history,
                   with_tangent,
                   scratch.responses[q],
                   new_history == nullptr ? nullptr : new_history + q * n_history);
  }



  template <int dim>
  void
  BodyResponse<dim>::keep_corner_jacobian(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    CellScratch                                          &scratch) const
  {
    // A cell folded at a corner can have det F > 0 at its Gauss points
    // (the Gauss-Lobatto points include the corners).
    std::array<Point<dim>, GeometryInfo<dim>::vertices_per_cell>     vertices;
    std::array<Tensor<1, dim>, GeometryInfo<dim>::vertices_per_cell> displacement;
    for (unsigned int a = 0; a < scratch.dof.size(); ++a)
      {
        vertices[a] = cell->vertex(a);
        for (unsigned int c = 0; c < dim; ++c)
          displacement[a][c] = scratch.u(scratch.dof[a][c]);
      }
    const double jacobian = smallest_corner_jacobian<dim>(vertices, displacement);
    if (jacobian < scratch.smallest_jacobian.value)
      scratch.smallest_jacobian.keep(jacobian, cell->center());
  }



  template <int dim>
  types::global_dof_index
  BodyResponse<dim>::internal_force(const Vector                    &u_ghosted,
                                    const AffineConstraints<double> &distribute,
                                    Vector                          &force,
                                    TrilinosWrappers::SparseMatrix  *tangent) const
  {
    const DoFHandler<dim> &dof_handler = body.get_dof_handler();
    CellScratch           &scratch = fresh_scratch();
    force = 0;
    if (tangent != nullptr)
      *tangent = 0;
    // The forces of the cells that have positions (none constrained) by
    // their local rows.
    double *const force_values = tangent == nullptr ? positions.local_values(force) : nullptr;
    types::global_dof_index plastic_points = 0;
    double                  element_forces = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          evaluate_cell(cell, u_ghosted, tangent != nullptr, scratch, nullptr);
          for (unsigned int q = 0; q < scratch.n_points; ++q)
            plastic_points += scratch.responses[q].plastic ? 1 : 0;
          cell_force_and_tangent(materials.of(cell->material_id()).elastic().mean_dilatation,
                                 tangent != nullptr,
                                 scratch);
          element_forces += scratch.force.norm_sqr();
          cell->get_dof_indices(scratch.dof_indices);
          if (tangent != nullptr)
            distribute.distribute_local_to_global(
              scratch.matrix, scratch.force, scratch.dof_indices, *tangent, force);
          else
            add_cell_force(cell->active_cell_index(), scratch, distribute, force, force_values);
        }
    force.compress(VectorOperation::add);
    if (tangent != nullptr)
      tangent->compress(VectorOperation::add);
    refuse_inverted_cells(scratch);
    element_force_size =
      std::sqrt(Utilities::MPI::sum(element_forces, body.get_mpi_communicator()));
    return Utilities::MPI::sum(plastic_points, body.get_mpi_communicator());
  }



  template <int dim>
  types::global_dof_index
  BodyResponse<dim>::update_tangent(const Vector                    &u_ghosted,
                                    const AffineConstraints<double> &constraints,
                                    Vector                          &force,
                                    TrilinosWrappers::SparseMatrix  &matrix)
  {
    const DoFHandler<dim> &dof_handler = body.get_dof_handler();
    const unsigned int     n_cells = dof_handler.get_triangulation().n_active_cells();
    // A cell whose points are all elastic now and were at the last tangent
    // adds the same (elastic) matrix: only the others are taken out at the
    // last tangent's displacement and put in at this one. At finite strain
    // every cell's matrix changes: all are assembled anew.
    const bool changed_cells_only = tangent_at.size() > 0 &&
                                    elastic_cells.size() == n_cells &&
                                    !materials.any_finite_strain();
    if (!changed_cells_only)
      {
        elastic_cells.assign(n_cells, 0);
        tangent_at.reinit(u_ghosted);
        matrix = 0;
      }
    positions.update(dof_handler, constraints, matrix);
    CellScratch       &scratch = fresh_scratch();
    FullMatrix<double> before(scratch.matrix.m(), scratch.matrix.n());
    force = 0;
    double *const force_values = positions.local_values(force);
    types::global_dof_index plastic_points = 0;
    double                  element_forces = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const unsigned int c = cell->active_cell_index();
          const bool b_bar     = materials.of(cell->material_id()).elastic().mean_dilatation;
          // Where every cell is assembled anew, its tangent is wanted now;
          // otherwise first whether the cell is elastic.
          evaluate_cell(cell, u_ghosted, !changed_cells_only, scratch, nullptr);
          bool elastic = true;
          for (unsigned int q = 0; q < scratch.n_points; ++q)
            {
              plastic_points += scratch.responses[q].plastic ? 1 : 0;
              elastic = elastic && !scratch.responses[q].plastic;
            }
          cell->get_dof_indices(scratch.dof_indices);
          if (changed_cells_only && elastic && elastic_cells[c])
            {
              cell_force_and_tangent(b_bar, false, scratch);
              element_forces += scratch.force.norm_sqr();
              add_cell_force(c, scratch, constraints, force, force_values);
              continue;
            }
          if (changed_cells_only)
            {
              evaluate_cell(cell, tangent_at, true, scratch, nullptr);
              cell_force_and_tangent(b_bar, true, scratch);
              before = scratch.matrix;
              evaluate_cell(cell, u_ghosted, true, scratch, nullptr);
            }
          cell_force_and_tangent(b_bar, true, scratch);
          element_forces += scratch.force.norm_sqr();
          if (changed_cells_only)
            scratch.matrix.add(-1., before);
          if (positions.has(c, scratch.dof_indices))
            {
              positions.add(c, scratch.matrix);
              add_cell_force(c, scratch, constraints, force, force_values);
            }
          else
            constraints.distribute_local_to_global(
              scratch.matrix, scratch.force, scratch.dof_indices, matrix, force);
          elastic_cells[c] = elastic;
        }
    force.compress(VectorOperation::add);
    matrix.compress(VectorOperation::add);
    refuse_inverted_cells(scratch);
    tangent_at = u_ghosted;
    element_force_size =
      std::sqrt(Utilities::MPI::sum(element_forces, body.get_mpi_communicator()));
    return Utilities::MPI::sum(plastic_points, body.get_mpi_communicator());
  }



  template <int dim>
  void
  BodyResponse<dim>::forget_tangent()
  {
    elastic_cells.clear();
    tangent_at.clear();
  }



  template <int dim>
  void
  BodyResponse<dim>::add_cell_force(const unsigned int               active_cell_index,
                                    const CellScratch               &scratch,
                                    const AffineConstraints<double> &constraints,
                                    Vector                          &force,
                                    double *const                    force_values) const
  {
    if (force_values != nullptr && positions.has(active_cell_index, scratch.dof_indices))
      positions.add_to_vector(active_cell_index, scratch.force, force_values);
    else
      constraints.distribute_local_to_global(scratch.force, scratch.dof_indices, force);
  }



  template <int dim>
  void
  BodyResponse<dim>::new_mesh()
  {
    forget_tangent();
    // The positions serve the matrix of this mesh once update_tangent()
    // has taken them (internal_force() adds by them before that).
    positions = CellMatrixPositions<dim>();
    // An axisymmetric cell takes its points' radii and values from its
    // FEValues each time.
    if (materials.all_linear() || materials.axisymmetric())
      return;
    CellScratch &scratch = fresh_scratch();
    reference.reinit(body.get_dof_handler(),
                     scratch.gauss_values,
                     scratch.lobatto_values,
                     [this](const typename DoFHandler<dim>::active_cell_iterator &cell) {
                       return materials.of(cell->material_id()).elastic().corner_points;
                     });
  }



  template <int dim>
  void
  BodyResponse<dim>::commit(const Vector &u_ghosted)
  {
    // The matrix was the tangent of the history now replaced.
    forget_tangent();
    if (!history.active())
      return;
    const DoFHandler<dim> &dof_handler = body.get_dof_handler();
    CellScratch           &scratch = fresh_scratch();
    std::vector<double>    updated;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        if (double *values = history.values(cell))
          {
            const unsigned int n =
              scratch.gauss.size() * materials.history_size(cell->material_id());
            updated.resize(n);
            evaluate_cell(cell, u_ghosted, false, scratch, updated.data());
            std::copy(updated.begin(), updated.end(), values);
          }
  }



  template <int dim>
  PlacedMinimum<dim>
  BodyResponse<dim>::smallest_jacobian(const Vector &u_ghosted) const
  {
    const DoFHandler<dim> &dof_handler = body.get_dof_handler();
    CellScratch           &scratch = fresh_scratch();
    if (finite_strain())
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          evaluate_cell(cell, u_ghosted, false, scratch, nullptr);
    return scratch.smallest_jacobian.over_ranks(body.get_mpi_communicator());
  }



  template <int dim>
  std::vector<CellState<dim>>
  BodyResponse<dim>::cell_states(const Vector &u_ghosted) const
  {
    const DoFHandler<dim> &dof_handler = body.get_dof_handler();
    CellScratch           &scratch = fresh_scratch();
    std::vector<CellState<dim>> states(
      dof_handler.get_triangulation().n_active_cells());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          evaluate_cell(cell, u_ghosted, false, scratch, nullptr);
          const unsigned int        n_points  = scratch.n_points;
          const MaterialModel<dim> &law       = materials.of(cell->material_id());
          const double             *committed = history.values(cell);
          CellState<dim>           &state     = states[cell->active_cell_index()];
          if constexpr (dim == 2)
            if (scratch.revolved)
              {
                revolved_cell_state(scratch, committed, cell->material_id(), state);
                continue;
              }
          // At finite strain the Cauchy stress sigma = F S F^T / J
          // (sigma_zz = S_zz / J in plane strain), averaged over the
          // deformed cell.
          const std::vector<double> &jacobian = scratch.jacobian;
          double                     volume = 0, reference_volume = 0;
          for (unsigned int q = 0; q < n_points; ++q)
            {
              volume += jacobian[q] * scratch.JxW[q];
              reference_volume += scratch.JxW[q];
            }
          state.jacobian = volume / reference_volume;
          for (unsigned int q = 0; q < n_points; ++q)
            {
              const MaterialResponse<dim> &r = scratch.responses[q];
              const double weight = jacobian[q] * scratch.JxW[q] / volume;
              SymmetricTensor<2, dim> stress       = r.stress;
              double                  out_of_plane = r.out_of_plane_stress;
              if (scratch.finite_strain)
                {
                  const Tensor<2, dim> &F = scratch.deformation_gradient[q];
                  stress = symmetrize(F * Tensor<2, dim>(r.stress) * transpose(F)) /
                           jacobian[q];
                  out_of_plane /= jacobian[q];
                }
              SymmetricTensor<2, 3> stress_3d;
              for (unsigned int i = 0; i < dim; ++i)
                for (unsigned int j = i; j < dim; ++j)
                  stress_3d[i][j] = stress[i][j];
              if (dim == 2)
                stress_3d[2][2] = out_of_plane;
              state.stress += weight * stress;
              state.out_of_plane_stress += weight * out_of_plane;
              state.mean_stress += weight * trace(stress_3d) / 3.;
              state.von_mises_stress +=
                weight * std::sqrt(1.5) * deviator(stress_3d).norm();
              if (committed != nullptr)
                {
                  const double *point = committed + q * law.n_history_values();
                  state.equivalent_plastic_strain +=
                    weight * law.equivalent_plastic_strain(point);
                  state.plastic_strain += weight * law.plastic_strain(point);
                }
              if (r.at_yield)
                state.yield_state = 2;
            }
          if (state.yield_state == 0 && state.equivalent_plastic_strain > 0)
            state.yield_state = 1;
        }
    return states;
  }

  template class BodyResponse<2>;
  template class BodyResponse<3>;
} // namespace FrictionalContact
