#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/distributed/tria_base.h>
#include <deal.II/numerics/vector_tools.h>

#include <frictional_contact/model/axisymmetry.h>
#include <frictional_contact/model/elastic_body.h>
#include <frictional_contact/solvers/matrix_free_stiffness.h>

namespace FrictionalContact
{
  template <int dim>
  ElasticBody<dim>::ElasticBody(
    const parallel::distributed::Triangulation<dim> &triangulation,
    const Materials<dim>                            &materials,
    const BoundaryConditions<dim>                   &conditions,
    const std::map<std::string, types::material_id> &bodies,
    const bool                                       matrix_free)
    : materials(materials)
    , conditions(conditions)
    , bodies(bodies)
    , mpi_communicator(triangulation.get_communicator())
    , fe(FE_Q<dim>(1), dim)
    , dof_handler(triangulation)
    , matrix_free(matrix_free)
    , volumetric(materials)
  {}



  template <int dim>
  void
  ElasticBody<dim>::setup()
  {
    dof_handler.distribute_dofs(fe);
    // A mesh made with its levels (for geometric multigrid) gets their dofs.
    if (const auto *mesh = dynamic_cast<const parallel::TriangulationBase<dim> *>(
          &dof_handler.get_triangulation());
        mesh != nullptr && mesh->is_multilevel_hierarchy_constructed())
      dof_handler.distribute_mg_dofs();
    owned_dofs    = dof_handler.locally_owned_dofs();
    relevant_dofs = DoFTools::extract_locally_relevant_dofs(dof_handler);

    constraints.clear();
    constraints.reinit(relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    hanging_node_constraints.clear();
    hanging_node_constraints.reinit(relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, hanging_node_constraints);
    hanging_node_constraints.close();
    for (const auto &fixed : conditions.fixed_boundaries)
      VectorTools::interpolate_boundary_values(dof_handler,
                                               fixed.id,
                                               Functions::ZeroFunction<dim>(dim),
                                               constraints,
                                               fixed.components);
    // The increments of prescribed displacements are set by a lifting
    // (prescribed_increment()); for the solves these dofs are held too.
    prescribed_dofs.clear();
    prescribed_dofs.set_size(dof_handler.n_dofs());
    for (const auto &prescribed : conditions.prescribed_boundaries)
      {
        std::map<types::global_dof_index, double> values;
        VectorTools::interpolate_boundary_values(dof_handler,
                                                 prescribed.id,
                                                 Functions::ZeroFunction<dim>(dim),
                                                 values,
                                                 prescribed.components);
        for (const auto &[dof, value] : values)
          if (!constraints.is_constrained(dof) && owned_dofs.is_element(dof))
            prescribed_dofs.add_index(dof);
        VectorTools::interpolate_boundary_values(dof_handler,
                                                 prescribed.id,
                                                 Functions::ZeroFunction<dim>(dim),
                                                 constraints,
                                                 prescribed.components);
      }
    prescribed_dofs.compress();
    if (materials.axisymmetric())
      Axisymmetry::hold_axis(dof_handler, Axisymmetry::check_radii(dof_handler), constraints);
    constraints.close();

    for (unsigned int c = 0; c < dim; ++c)
      {
        std::vector<bool> mask(dim, false);
        mask[c]           = true;
        component_dofs[c] = DoFTools::extract_dofs(dof_handler, ComponentMask(mask));
      }

    types::global_dof_index n_free_here = 0;
    for (const auto i : owned_dofs)
      if (!constraints.is_constrained(i))
        ++n_free_here;
    n_free = Utilities::MPI::sum(n_free_here, mpi_communicator);

    load.reinit(owned_dofs, mpi_communicator);
    if (matrix_free)
      {
        stiffness_operator = std::make_unique<MatrixFreeStiffness<dim>>(
          dof_handler, constraints, lame_parameters());
        return;
      }
    TrilinosWrappers::SparsityPattern sparsity(owned_dofs,
                                               owned_dofs,
                                               relevant_dofs,
                                               mpi_communicator);
    DoFTools::make_sparsity_pattern(dof_handler,
                                    sparsity,
                                    constraints,
                                    /*keep_constrained_dofs=*/false,
                                    Utilities::MPI::this_mpi_process(
                                      mpi_communicator));
    sparsity.compress();
    stiffness_matrix.reinit(sparsity);
    stiffness_operator = std::make_unique<AssembledStiffness>(stiffness_matrix);
    // The split of K holds for linear laws only: a tangent changes at each
    // Newton step.
    if (materials.all_linear())
      volumetric.setup(dof_handler, constraints, stiffness_matrix);
  }



  template <int dim>
  ElasticBody<dim>::CellScratch::CellScratch(const FiniteElement<dim> &fe)
    : quadrature(2)
    , face_quadrature(2)
    , fe_values(fe,
                quadrature,
                update_values | update_gradients | update_quadrature_points |
                  update_JxW_values)
    , fe_face_values(fe,
                     face_quadrature,
                     update_values | update_normal_vectors | update_quadrature_points |
                       update_JxW_values)
    , cell_matrix(fe.n_dofs_per_cell(), fe.n_dofs_per_cell())
    , cell_load(fe.n_dofs_per_cell())
    , dof_indices(fe.n_dofs_per_cell())
    , divergence_integral(fe.n_dofs_per_cell())
  {}



  template <int dim>
  void
  ElasticBody<dim>::cell_stiffness(const types::material_id id, CellScratch &scratch) const
  {
    if constexpr (dim == 2)
      if (materials.axisymmetric())
        return Axisymmetry::cell_stiffness(materials.revolved(id).elastic(),
                                           scratch.fe_values,
                                           scratch.cell_matrix,
                                           scratch.divergence_integral,
                                           scratch.volume);
    const ElasticConstants<dim> &material = materials.of(id).elastic();
    const FEValues<dim>             &fe_values     = scratch.fe_values;
    FullMatrix<double>              &cell_matrix   = scratch.cell_matrix;
    const FEValuesExtractors::Vector displacement(0);
    const SymmetricTensor<4, dim>   &C             = material.stress_strain_tensor();
    const unsigned int               dofs_per_cell = fe.n_dofs_per_cell();

    cell_matrix = 0;
    std::vector<SymmetricTensor<2, dim>> strain(dofs_per_cell);
    // B-bar: the shear part at the Gauss points, the volumetric part from
    // the cell integrals of div phi_i (the mean dilatation).
    std::vector<double> &divergence_integral = scratch.divergence_integral;
    double              &volume              = scratch.volume;
    std::fill(divergence_integral.begin(), divergence_integral.end(), 0.);
    volume = 0;
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          strain[i] = fe_values[displacement].symmetric_gradient(i, q);
        const double JxW = fe_values.JxW(q);
        volume += JxW;
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          {
            const SymmetricTensor<2, dim> stress_i =
              material.mean_dilatation ?
                material.stress(strain[i], 0.) :
                SymmetricTensor<2, dim>(C * strain[i]);
            divergence_integral[i] += trace(strain[i]) * JxW;
            for (unsigned int j = 0; j <= i; ++j)
              cell_matrix(i, j) += (stress_i * strain[j]) * JxW;
          }
      }
    if (material.mean_dilatation)
      for (unsigned int i = 0; i < dofs_per_cell; ++i)
        for (unsigned int j = 0; j <= i; ++j)
          cell_matrix(i, j) += material.bulk_modulus * divergence_integral[i] *
                               divergence_integral[j] / volume;
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      for (unsigned int j = i + 1; j < dofs_per_cell; ++j)
        cell_matrix(i, j) = cell_matrix(j, i);
  }



  template <int dim>
  void
  ElasticBody<dim>::assemble_cell(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    CellScratch                                          &scratch,
    const bool                                            with_matrix) const
  {
    FEValues<dim>                   &fe_values      = scratch.fe_values;
    FEFaceValues<dim>               &fe_face_values = scratch.fe_face_values;
    dealii::Vector<double>          &cell_load      = scratch.cell_load;
    const FEValuesExtractors::Vector displacement(0);
    const unsigned int               dofs_per_cell = fe.n_dofs_per_cell();

    // An axisymmetric scene's loads are totals over the revolution.
    const bool axisymmetric = materials.axisymmetric();
    const auto weight       = [axisymmetric](const Point<dim> &point) {
      return axisymmetric ? Axisymmetry::weight(point) : 1.;
    };
    fe_values.reinit(cell);
    cell_load = 0;
    for (const unsigned int q : fe_values.quadrature_point_indices())
      for (unsigned int i = 0; i < dofs_per_cell; ++i)
        cell_load(i) += conditions.body_force * fe_values[displacement].value(i, q) *
                        fe_values.JxW(q) * weight(fe_values.quadrature_point(q));
    if (with_matrix)
      cell_stiffness(cell->material_id(), scratch);

    for (const auto &face : cell->face_iterators())
      if (face->at_boundary())
        {
          const auto t = conditions.tractions.find(face->boundary_id());
          const auto p = conditions.pressures.find(face->boundary_id());
          if (t == conditions.tractions.end() && p == conditions.pressures.end())
            continue;
          fe_face_values.reinit(cell, face);
          for (const unsigned int q : fe_face_values.quadrature_point_indices())
            {
              Tensor<1, dim> traction;
              if (t != conditions.tractions.end())
                traction += t->second;
              if (p != conditions.pressures.end())
                traction -= p->second * fe_face_values.normal_vector(q);
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                cell_load(i) += traction * fe_face_values[displacement].value(i, q) *
                                fe_face_values.JxW(q) *
                                weight(fe_face_values.quadrature_point(q));
            }
        }
  }



  template <int dim>
  void
  ElasticBody<dim>::assemble()
  {
    CellScratch        scratch(fe);
    const unsigned int dofs_per_cell = fe.n_dofs_per_cell();

    if (!matrix_free)
      stiffness_matrix = 0;
    load = 0;
    volumetric.start_assembly();
    Tensor<1, dim> total_here;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          assemble_cell(cell, scratch, !matrix_free);
          for (unsigned int i = 0; i < dofs_per_cell; ++i)
            total_here[fe.system_to_component_index(i).first] +=
              scratch.cell_load(i);
          cell->get_dof_indices(scratch.dof_indices);
          if (volumetric.active())
            volumetric.add_cell(cell,
                                scratch.cell_matrix,
                                scratch.divergence_integral,
                                scratch.volume,
                                scratch.dof_indices,
                                constraints);
          if (matrix_free)
            constraints.distribute_local_to_global(scratch.cell_load,
                                                   scratch.dof_indices,
                                                   load);
          else
            constraints.distribute_local_to_global(scratch.cell_matrix,
                                                   scratch.cell_load,
                                                   scratch.dof_indices,
                                                   stiffness_matrix,
                                                   load);
        }
    if (!matrix_free)
      {
        stiffness_matrix.compress(VectorOperation::add);
        volumetric.finish_assembly(stiffness_matrix, constraints);
      }
    load.compress(VectorOperation::add);
    reference_total_load = Utilities::MPI::sum(total_here, mpi_communicator);
    if (materials.axisymmetric())
      reference_total_load = Axisymmetry::revolution_total(reference_total_load);
  }



  template <int dim>
  LameParameters
  ElasticBody<dim>::lame_parameters() const
  {
    // From each body's stress-strain tensor: C_0011 = lambda, C_0101 = mu.
    LameParameters lame;
    for (const auto &[name, id] : bodies)
      {
        const SymmetricTensor<4, dim> &C = materials.of(id).elastic().stress_strain_tensor();
        lame[id] = {{C[0][0][1][1], C[0][1][0][1]}};
      }
    return lame;
  }



  template <int dim>
  LameParameters
  ElasticBody<dim>::reduced_lame_parameters() const
  {
    LameParameters lame = lame_parameters();
    for (auto &[id, lambda_mu] : lame)
      lambda_mu =
        VolumetricBlocks<dim>::reduced_lame_parameters(materials.of(id).elastic(), lambda_mu);
    return lame;
  }



  template <int dim>
  void
  ElasticBody<dim>::internal_force(const Vector &u, Vector &force) const
  {
    if (conditions.prescribed_boundaries.empty())
      {
        // u is zero on all constrained dofs: the condensed K does it.
        stiffness_operator->vmult(force, u);
        return;
      }
    Vector u_ghosted = make_ghosted_vector();
    u_ghosted        = u;
    element_forces(u_ghosted, 0., constraints, force);
  }



  template <int dim>
  void
  ElasticBody<dim>::element_forces(const Vector                    &u_ghosted,
                                   const double                     load_factor,
                                   const AffineConstraints<double> &distribute,
                                   Vector                          &force) const
  {
    CellScratch            scratch(fe);
    dealii::Vector<double> cell_u(fe.n_dofs_per_cell()),
      cell_force(fe.n_dofs_per_cell());

    force = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          assemble_cell(cell, scratch);
          cell->get_dof_values(u_ghosted, cell_u);
          scratch.cell_matrix.vmult(cell_force, cell_u);
          cell_force.add(-load_factor, scratch.cell_load);
          cell->get_dof_indices(scratch.dof_indices);
          distribute.distribute_local_to_global(cell_force,
                                                scratch.dof_indices,
                                                force);
        }
    force.compress(VectorOperation::add);
  }



  template <int dim>
  double
  ElasticBody<dim>::largest_nodal_magnitude(const Vector &u) const
  {
    // The dofs of a vertex all belong to the rank that owns its first one.
    double largest = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          if (owned_dofs.is_element(cell->vertex_dof_index(v, 0)))
            {
              double square = 0;
              for (unsigned int c = 0; c < dim; ++c)
                square += std::pow(u[cell->vertex_dof_index(v, c)], 2);
              largest = std::max(largest, square);
            }
    return std::sqrt(Utilities::MPI::max(largest, mpi_communicator));
  }



  template <int dim>
  std::vector<std::vector<double>>
  ElasticBody<dim>::rigid_body_modes() const
  {
    const unsigned int n_modes = dim * (dim + 1) / 2;
    std::vector<std::vector<double>> modes(
      n_modes, std::vector<double>(owned_dofs.n_elements(), 0.));
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            const Point<dim> &x = cell->vertex(v);
            for (unsigned int c = 0; c < dim; ++c)
              {
                const auto g = cell->vertex_dof_index(v, c);
                if (!owned_dofs.is_element(g))
                  continue;
                const auto row = owned_dofs.index_within_set(g);
                modes[c][row] = 1.;
                if (dim == 2)
                  modes[2][row] = (c == 0 ? -x[1] : x[0]);
                else
                  {
                    // Rotations about the x, y and z axes.
                    const unsigned int a = (c + 1) % dim, b = (c + 2) % dim;
                    modes[dim + b][row] = x[a];
                    modes[dim + a][row] = -x[b];
                  }
              }
          }
    return modes;
  }



  template <int dim>
  std::set<types::material_id>
  ElasticBody<dim>::bodies_free_to_move() const
  {
    // The fixed dofs of a body prevent its rigid motions iff the rigid-body
    // modes, restricted to them, are linearly independent: their Gram
    // matrix is then positive definite. Bodies share no vertex.
    std::vector<std::vector<double>> modes = rigid_body_modes();
    // A body of revolution has one rigid motion: along its axis (y).
    if (materials.axisymmetric())
      modes = {modes[1]};
    const unsigned int n_modes = modes.size();
    std::map<types::material_id, unsigned int> body_index;
    for (const auto &[name, id] : bodies)
      body_index.emplace(id, body_index.size());
    std::vector<int> body_of_row(owned_dofs.n_elements(), -1);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int c = 0; c < dim; ++c)
            if (const auto g = cell->vertex_dof_index(v, c); owned_dofs.is_element(g))
              body_of_row[owned_dofs.index_within_set(g)] =
                body_index.at(cell->material_id());

    std::vector<double> gram(bodies.size() * n_modes * n_modes, 0.);
    unsigned int        row = 0;
    for (const auto g : owned_dofs)
      {
        if (is_fixed(g) && body_of_row[row] >= 0)
          for (unsigned int a = 0; a < n_modes; ++a)
            for (unsigned int b = 0; b < n_modes; ++b)
              gram[(body_of_row[row] * n_modes + a) * n_modes + b] +=
                modes[a][row] * modes[b][row];
        ++row;
      }
    Utilities::MPI::sum(gram, mpi_communicator, gram);

    std::set<types::material_id> free_to_move;
    for (const auto &[name, id] : bodies)
      {
        const unsigned int       k = body_index.at(id);
        LAPACKFullMatrix<double> matrix(n_modes, n_modes);
        double                   scale = 0;
        for (unsigned int a = 0; a < n_modes; ++a)
          for (unsigned int b = 0; b < n_modes; ++b)
            {
              matrix(a, b) = gram[(k * n_modes + a) * n_modes + b];
              scale        = std::max(scale, std::abs(matrix(a, b)));
            }
        matrix.compute_eigenvalues();
        double smallest = std::numeric_limits<double>::max();
        for (unsigned int a = 0; a < n_modes; ++a)
          smallest = std::min(smallest, matrix.eigenvalue(a).real());
        if (!(scale > 0) || smallest < 1e-10 * scale)
          free_to_move.insert(id);
      }
    return free_to_move;
  }



  template <int dim>
  std::vector<bool>
  ElasticBody<dim>::owned_dofs_of(const std::set<types::material_id> &ids) const
  {
    std::vector<bool> in(owned_dofs.n_elements(), false);
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && ids.count(cell->material_id()) > 0)
        {
          cell->get_dof_indices(dof_indices);
          for (const auto g : dof_indices)
            if (owned_dofs.is_element(g))
              in[owned_dofs.index_within_set(g)] = true;
        }
    return in;
  }

  template class ElasticBody<2>;
  template class ElasticBody<3>;
} // namespace FrictionalContact
