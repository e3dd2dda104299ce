// The definitions of ElasticityOperator's members, instantiated by
// elasticity_operator_2d.cc and elasticity_operator_3d.cc (CMakeLists.txt
// says why two units).
#pragma once

#include <deal.II/matrix_free/fe_evaluation.h>
#include <deal.II/matrix_free/tools.h>

#include <frictional_contact/solvers/elasticity_operator.h>

namespace FrictionalContact
{
  namespace
  {
    /// The stress at every quadrature point of @p phi (whose gradients are
    /// evaluated), submitted for the integration against the test
    /// functions' symmetric gradients.
    template <int dim, typename number>
    void
    submit_stress(FEEvaluation<dim, 1, 2, dim, number> &phi,
                  const VectorizedArray<number>        &lambda,
                  const VectorizedArray<number>        &two_mu)
    {
      // On the gradients in reference coordinates, in place: with deal.II's
      // one-lane VectorizedArray, get_gradient() and submit_gradient()
      // return and take tensors that GCC copies through the stack, which
      // stalled every quadrature point (doc/performance.md, "Geometric
      // multigrid"). J^{-T} is constant on affine cells.
      using Number                  = VectorizedArray<number>;
      const unsigned int n_q_points = phi.n_q_points;
      Number            *gradients  = phi.begin_gradients();
      const auto         cell_type = phi.get_cell_type();
      const bool         constant_jacobian =
        cell_type <= internal::MatrixFreeFunctions::affine;
      const bool cartesian = cell_type == internal::MatrixFreeFunctions::cartesian;
      const Number mu = number(0.5) * two_mu;
      Number       inverse[dim][dim];
      for (const unsigned int q : phi.quadrature_point_indices())
        {
          if (q == 0 || !constant_jacobian)
            {
              const Tensor<2, dim, Number> jacobian = phi.inverse_jacobian(q);
              for (unsigned int i = 0; i < dim; ++i)
                for (unsigned int j = 0; j < dim; ++j)
                  inverse[i][j] = jacobian[i][j];
            }
          // The gradient in real coordinates, G[c][i] = d u_c / d x_i.
          Number G[dim][dim];
          for (unsigned int c = 0; c < dim; ++c)
            for (unsigned int i = 0; i < dim; ++i)
              if (cartesian)
                G[c][i] = inverse[i][i] * gradients[(c * dim + i) * n_q_points + q];
              else
              {
                G[c][i] = inverse[i][0] * gradients[(c * dim) * n_q_points + q];
                for (unsigned int j = 1; j < dim; ++j)
                  G[c][i] += inverse[i][j] * gradients[(c * dim + j) * n_q_points + q];
              }
          const Number JxW = phi.JxW(q);
          // The stress times JxW, symmetric.
          Number volumetric = G[0][0];
          for (unsigned int d = 1; d < dim; ++d)
            volumetric += G[d][d];
          volumetric *= lambda;
          for (unsigned int d = 0; d < dim; ++d)
            {
              for (unsigned int e = d + 1; e < dim; ++e)
                G[d][e] = G[e][d] = JxW * mu * (G[d][e] + G[e][d]);
              G[d][d] = JxW * (two_mu * G[d][d] + volumetric);
            }
          // Back to reference coordinates for the integration.
          for (unsigned int c = 0; c < dim; ++c)
            for (unsigned int j = 0; j < dim; ++j)
              if (cartesian)
                gradients[(c * dim + j) * n_q_points + q] = inverse[j][j] * G[c][j];
              else
              {
                Number sum = inverse[0][j] * G[c][0];
                for (unsigned int i = 1; i < dim; ++i)
                  sum += inverse[i][j] * G[c][i];
                gradients[(c * dim + j) * n_q_points + q] = sum;
              }
        }
    }
  } // namespace



  template <int dim, typename number>
  void
  ElasticityOperator<dim, number>::set_materials(const LameParameters &lame)
  {
    const MatrixFree<dim, number> &data      = *this->data;
    const unsigned int             n_batches = data.n_cell_batches();
    moduli.reinit(n_batches, 2);
    stiffness_diagonal.reinit(0);
    for (unsigned int batch = 0; batch < n_batches; ++batch)
      {
        const unsigned int filled = data.n_active_entries_per_cell_batch(batch);
        // The lanes past the last cell repeat it (their results are unused).
        for (unsigned int lane = 0; lane < VectorizedArray<number>::size(); ++lane)
          {
            const auto cell = data.get_cell_iterator(batch, std::min(lane, filled - 1));
            const auto &[lambda, mu] = lame.at(cell->material_id());
            moduli(batch, 0)[lane] = lambda;
            moduli(batch, 1)[lane] = 2 * mu;
          }
      }
  }



  template <int dim, typename number>
  void
  ElasticityOperator<dim, number>::set_springs(std::vector<Spring> new_springs)
  {
    springs = std::move(new_springs);
  }



  template <int dim, typename number>
  void
  ElasticityOperator<dim, number>::clear()
  {
    moduli.reinit(0, 0);
    springs.clear();
    stiffness_diagonal.reinit(0);
    MatrixFreeOperators::Base<dim, VectorType>::clear();
  }



  template <int dim, typename number>
  void
  ElasticityOperator<dim, number>::apply_add(VectorType &dst, const VectorType &src) const
  {
    this->data->cell_loop(&ElasticityOperator::local_apply, this, dst, src);
    for (const Spring &spring : springs)
      for (unsigned int a = 0; a < spring.rows.size(); ++a)
        for (unsigned int b = 0; b < spring.rows.size(); ++b)
          dst.local_element(spring.rows[a]) +=
            spring.values[a * spring.rows.size() + b] * src.local_element(spring.rows[b]);
  }



  template <int dim, typename number>
  void
  ElasticityOperator<dim, number>::local_apply(
    const MatrixFree<dim, number>               &data,
    VectorType                                  &dst,
    const VectorType                            &src,
    const std::pair<unsigned int, unsigned int> &cell_range) const
  {
    FEEvaluation<dim, 1, 2, dim, number> phi(data);
    for (unsigned int batch = cell_range.first; batch < cell_range.second; ++batch)
      {
        phi.reinit(batch);
        phi.gather_evaluate(src, EvaluationFlags::gradients);
        submit_stress(phi, moduli(batch, 0), moduli(batch, 1));
        phi.integrate_scatter(EvaluationFlags::gradients, dst);
      }
  }



  template <int dim, typename number>
  void
  ElasticityOperator<dim, number>::compute_diagonal()
  {
    // K's diagonal once (it costs about as many operator applications as a
    // cell has dofs), the springs' added at every call.
    if (stiffness_diagonal.size() == 0)
      {
        this->data->initialize_dof_vector(stiffness_diagonal);
        const std::function<void(FEEvaluation<dim, 1, 2, dim, number> &)> cell_operation =
          [this](FEEvaluation<dim, 1, 2, dim, number> &phi) { integrate_stiffness(phi); };
        MatrixFreeTools::compute_diagonal(*this->data, stiffness_diagonal, cell_operation);
      }
    this->inverse_diagonal_entries.reset(new DiagonalMatrix<VectorType>());
    VectorType &inverse = this->inverse_diagonal_entries->get_vector();
    inverse             = stiffness_diagonal;
    for (const Spring &spring : springs)
      for (unsigned int a = 0; a < spring.rows.size(); ++a)
        inverse.local_element(spring.rows[a]) +=
          spring.values[a * spring.rows.size() + a];
    this->set_constrained_entries_to_one(inverse);
    for (number &entry : inverse)
      entry = entry > 0 ? number(1) / entry : number(1);
  }

  template <int dim, typename number>
  void
  ElasticityOperator<dim, number>::integrate_stiffness(
    FEEvaluation<dim, 1, 2, dim, number> &phi) const
  {
    const unsigned int batch = phi.get_current_cell_index();
    phi.evaluate(EvaluationFlags::gradients);
    submit_stress(phi, moduli(batch, 0), moduli(batch, 1));
    phi.integrate(EvaluationFlags::gradients);
  }



  template <int dim, typename number>
  std::vector<FullMatrix<double>>
  ElasticityOperator<dim, number>::cell_matrices(const unsigned int batch) const
  {
    // Column by column: the operator of the cell applied to unit vectors.
    FEEvaluation<dim, 1, 2, dim, number> phi(*this->data);
    phi.reinit(batch);
    const unsigned int n_dofs = phi.dofs_per_cell;
    const unsigned int filled = this->data->n_active_entries_per_cell_batch(batch);
    std::vector<FullMatrix<double>> matrices(filled, FullMatrix<double>(n_dofs, n_dofs));
    for (unsigned int column = 0; column < n_dofs; ++column)
      {
        for (unsigned int i = 0; i < n_dofs; ++i)
          phi.begin_dof_values()[i] = VectorizedArray<number>(i == column ? 1 : 0);
        integrate_stiffness(phi);
        for (unsigned int lane = 0; lane < filled; ++lane)
          for (unsigned int i = 0; i < n_dofs; ++i)
            matrices[lane](i, column) = phi.begin_dof_values()[i][lane];
      }
    return matrices;
  }

} // namespace FrictionalContact
