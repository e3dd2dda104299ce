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
      for (const unsigned int q : phi.quadrature_point_indices())
        {
          const SymmetricTensor<2, dim, VectorizedArray<number>> strain =
            phi.get_symmetric_gradient(q);
          SymmetricTensor<2, dim, VectorizedArray<number>> stress = two_mu * strain;
          const VectorizedArray<number> volumetric = lambda * trace(strain);
          for (unsigned int d = 0; d < dim; ++d)
            stress[d][d] += volumetric;
          phi.submit_symmetric_gradient(stress, q);
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
          [&](FEEvaluation<dim, 1, 2, dim, number> &phi) {
            const unsigned int batch = phi.get_current_cell_index();
            phi.evaluate(EvaluationFlags::gradients);
            submit_stress(phi, moduli(batch, 0), moduli(batch, 1));
            phi.integrate(EvaluationFlags::gradients);
          };
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

  template class ElasticityOperator<2, double>;
  template class ElasticityOperator<3, double>;
  template class ElasticityOperator<2, float>;
  template class ElasticityOperator<3, float>;
} // namespace FrictionalContact
