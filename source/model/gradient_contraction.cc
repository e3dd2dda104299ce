#include <frictional_contact/model/gradient_contraction.h>

#include <algorithm>

namespace FrictionalContact
{
  template <int dim>
  void
  GradientContraction<dim>::reinit(const unsigned int n_points)
  {
    // Every entry is written by add_point(): no zeroing.
    const unsigned int columns = dim * dim * n_vertices;
    if (weighted_gradients.m() != n_points * dim)
      {
        weighted_gradients.reinit(n_points * dim, n_vertices, true);
        gradients_through_tensor.reinit(n_points * dim, columns, true);
      }
    if (product.m() != n_vertices)
      product.reinit(n_vertices, columns, true);
    n_added = 0;
  }



  template <int dim>
  void
  GradientContraction<dim>::add_point(const unsigned int                 q,
                                      const double                       JxW,
                                      const std::vector<Tensor<1, dim>> &G,
                                      const double (&A)[dim][dim][dim][dim])
  {
    ++n_added;
    // The gradients by component, each a row over the vertices.
    double by_component[dim][n_vertices];
    for (unsigned int b = 0; b < n_vertices; ++b)
      for (unsigned int L = 0; L < dim; ++L)
        by_component[L][b] = G[b][L];
    for (unsigned int J = 0; J < dim; ++J)
      {
        const unsigned int row = q * dim + J;
        for (unsigned int a = 0; a < n_vertices; ++a)
          weighted_gradients(row, a) = JxW * by_component[J][a];
        double *through = &gradients_through_tensor(row, 0);
        for (unsigned int c = 0; c < dim; ++c)
          for (unsigned int d = 0; d < dim; ++d, through += n_vertices)
            for (unsigned int b = 0; b < n_vertices; ++b)
              {
                double sum = 0;
                for (unsigned int L = 0; L < dim; ++L)
                  sum += A[c][J][d][L] * by_component[L][b];
                through[b] = sum;
              }
      }
  }



  template <int dim>
  void
  GradientContraction<dim>::add_to(const std::vector<std::array<unsigned int, dim>> &dof,
                                   FullMatrix<double> &matrix)
  {
    AssertDimension(n_added * dim, weighted_gradients.m());
    // product = weighted_gradients^T gradients_through_tensor: in 2D (4 x
    // 16 from 8 rows) as a sum of rank-one rows, which takes less than a
    // call to BLAS; in 3D (8 x 72 from 24 rows) BLAS's gemm is faster
    // (bench/finite_strain.py, Hertz 2D and 3D).
    if constexpr (dim == 2)
      {
        constexpr unsigned int columns = dim * dim * n_vertices;
        for (unsigned int a = 0; a < n_vertices; ++a)
          {
            double sum[columns] = {};
            for (unsigned int k = 0; k < weighted_gradients.m(); ++k)
              {
                const double  w       = weighted_gradients(k, a);
                const double *through = &gradients_through_tensor(k, 0);
                for (unsigned int j = 0; j < columns; ++j)
                  sum[j] += w * through[j];
              }
            std::copy(sum, sum + columns, &product(a, 0));
          }
      }
    else
      weighted_gradients.Tmmult(product, gradients_through_tensor);
    for (unsigned int a = 0; a < n_vertices; ++a)
      for (unsigned int c = 0; c < dim; ++c)
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double *K = &product(a, (c * dim + d) * n_vertices);
            for (unsigned int b = 0; b < n_vertices; ++b)
              matrix(dof[a][c], dof[b][d]) += K[b];
          }
  }

  template class GradientContraction<2>;
  template class GradientContraction<3>;
} // namespace FrictionalContact
