#include <deal.II/base/mpi.h>

#include <frictional_contact/solvers/sparse_contact_map.h>

#include <cmath>

namespace FrictionalContact
{
  template <int dim>
  SparseContactMap<dim>::SparseContactMap(
    std::vector<std::array<Column, dim>> global_columns,
    const double                         friction_coefficient,
    const IndexSet                      &owned_rows,
    const MPI_Comm                       comm)
    : cone(friction_coefficient)
    , owned_rows(owned_rows)
    , mpi_communicator(comm)
    , n_global(Utilities::MPI::sum<types::global_dof_index>(global_columns.size(),
                                                            comm))
  {
    columns.resize(global_columns.size());
    for (unsigned int j = 0; j < global_columns.size(); ++j)
      for (unsigned int k = 0; k < dim; ++k)
        for (const auto &[row, value] : global_columns[j][k])
          {
            AssertThrow(owned_rows.is_element(row),
                        ExcMessage("a column of T has a row that this rank "
                                   "does not own"));
            columns[j][k].emplace_back(owned_rows.index_within_set(row), value);
          }
  }



  template <int dim>
  Tensor<1, dim>
  SparseContactMap<dim>::local_part(const unsigned int j, const Vector &u) const
  {
    const double  *values = u.begin();
    Tensor<1, dim> local;
    for (unsigned int k = 0; k < dim; ++k)
      for (const auto &[row, value] : columns[j][k])
        local[k] += value * values[row];
    return local;
  }



  template <int dim>
  void
  SparseContactMap<dim>::apply(const std::vector<Tensor<1, dim>> &r,
                               Vector                            &f) const
  {
    f          = 0;
    double *entries = f.begin();
    for (unsigned int j = 0; j < columns.size(); ++j)
      for (unsigned int k = 0; k < dim; ++k)
        for (const auto &[row, value] : columns[j][k])
          entries[row] += value * r[j][k];
  }



  template <int dim>
  void
  SparseContactMap<dim>::add_reaction(const unsigned int    j,
                                      const Tensor<1, dim> &r_j,
                                      Vector               &f) const
  {
    double *entries = f.begin();
    for (unsigned int k = 0; k < dim; ++k)
      for (const auto &[row, value] : columns[j][k])
        entries[row] += value * r_j[k];
  }



  template <int dim>
  std::vector<double>
  SparseContactMap<dim>::normal_stiffness(const StiffnessOperator &stiffness) const
  {
    const TrilinosWrappers::SparseMatrix &K = stiffness.matrix("an FCLIB problem");
    std::vector<double> c(columns.size(), 0.);
    for (unsigned int j = 0; j < columns.size(); ++j)
      for (const auto &[row_a, value_a] : columns[j][0])
        for (const auto &[row_b, value_b] : columns[j][0])
          c[j] += value_a *
                  K.el(owned_rows.nth_index_in_set(row_a),
                       owned_rows.nth_index_in_set(row_b)) *
                  value_b;
    return c;
  }



  template <int dim>
  double
  SparseContactMap<dim>::largest_singular_value() const
  {
    // Power iteration x <- T^T T x / |T^T T x| from x = (1, ..., 1); the
    // Rayleigh quotient |T x|^2 / |x|^2 increases towards sigma_T^2.
    std::vector<Tensor<1, dim>> x(columns.size());
    for (auto &x_j : x)
      for (unsigned int k = 0; k < dim; ++k)
        x_j[k] = 1;
    Vector       T_x(owned_rows, mpi_communicator);
    double       estimate = 0;
    for (unsigned int iteration = 0; iteration < 10000; ++iteration)
      {
        double norm_x = 0;
        for (const auto &x_j : x)
          norm_x += x_j.norm_square();
        norm_x = std::sqrt(Utilities::MPI::sum(norm_x, mpi_communicator));
        if (norm_x == 0)
          return 0;
        for (auto &x_j : x)
          x_j /= norm_x;
        apply(x, T_x);
        const double previous = estimate;
        estimate              = T_x.l2_norm();
        for (unsigned int j = 0; j < columns.size(); ++j)
          x[j] = local_part(j, T_x);
        if (std::abs(estimate - previous) <= 1e-12 * estimate)
          break;
      }
    return estimate;
  }

  template class SparseContactMap<2>;
  template class SparseContactMap<3>;
} // namespace FrictionalContact
