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
  GradientContraction<dim>::add_point(const unsigned int    q,
                                      const double          JxW,
                                      const Tensor<1, dim> *G,
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
  GradientContraction<dim>::multiply()
  {
    if constexpr (dim == 3)
      weighted_gradients.Tmmult(product, gradients_through_tensor);
    else
      {
        // The product's 4 x 16 entries summed here, over the rows at
        // once: BLAS's dgemm call took 1,770 instructions for these 512
        // products (callgrind, the O-ring at finite strain).
        constexpr unsigned int columns = dim * dim * n_vertices;
        const unsigned int     rows    = weighted_gradients.m();
        for (unsigned int a = 0; a < n_vertices; ++a)
          {
            double sum[columns] = {};
            for (unsigned int r = 0; r < rows; ++r)
              {
                const double  w       = weighted_gradients(r, a);
                const double *through = &gradients_through_tensor(r, 0);
                for (unsigned int column = 0; column < columns; ++column)
                  sum[column] += w * through[column];
              }
            std::copy(sum, sum + columns, &product(a, 0));
          }
      }
  }



  template <int dim>
  void
  GradientContraction<dim>::add_to(const std::vector<std::array<unsigned int, dim>> &dof,
                                   FullMatrix<double> &matrix)
  {
    AssertDimension(n_added * dim, weighted_gradients.m());
    multiply();
    for (unsigned int a = 0; a < n_vertices; ++a)
      for (unsigned int c = 0; c < dim; ++c)
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double *K = &product(a, (c * dim + d) * n_vertices);
            for (unsigned int b = 0; b < n_vertices; ++b)
              matrix(dof[a][c], dof[b][d]) += K[b];
          }
  }



  template <int dim>
  void
  GradientContraction<dim>::symmetric_part_into(
    const std::vector<std::array<unsigned int, dim>> &dof,
    FullMatrix<double>                               &matrix)
  {
    AssertDimension(n_added * dim, weighted_gradients.m());
    multiply();
    // K_(a,c),(b,d) is product(a, (c dim + d) n_vertices + b).
    const auto K = [&](const unsigned int a,
                       const unsigned int c,
                       const unsigned int b,
                       const unsigned int d) {
      return product(a, (c * dim + d) * n_vertices + b);
    };
    for (unsigned int a = 0; a < n_vertices; ++a)
      for (unsigned int c = 0; c < dim; ++c)
        {
          const unsigned int i = dof[a][c];
          matrix(i, i)         = K(a, c, a, c);
          for (unsigned int b = 0; b < n_vertices; ++b)
            for (unsigned int d = 0; d < dim; ++d)
              {
                const unsigned int j = dof[b][d];
                if (j > i)
                  matrix(i, j) = matrix(j, i) = 0.5 * (K(a, c, b, d) + K(b, d, a, c));
              }
        }
  }

  template class GradientContraction<2>;
  template class GradientContraction<3>;
} // namespace FrictionalContact
