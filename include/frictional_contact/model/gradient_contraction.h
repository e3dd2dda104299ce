#pragma once

#include <deal.II/base/geometry_info.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>

#include <array>
#include <vector>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * The matrix of a Q1 cell of a fourth-order tensor A_q at its points,
   *   K_(a,c),(b,d) = sum_q JxW_q sum_J,L dN_a/dX_J A_q[c][J][d][L] dN_b/dX_L
   * (dof (a, c): component c at vertex a), as one matrix product: each
   * point adds dim rows to two matrices, the weighted gradients
   * JxW_q dN_a/dX_J and the gradients through the tensor
   * sum_L A_q[c][J][d][L] dN_b/dX_L, and add_to() or
   * symmetric_part_into() forms the first's transpose times the second
   * (in 3D FullMatrix::Tmmult, which takes BLAS's gemm at these sizes; in
   * 2D a loop of its own). Summing the entries per point and entry
   * instead took most of a 3D finite-strain solve (doc/performance.md,
   * "Finite strain against small strain"). Owns the two matrices and the
   * product.
   */
  template <int dim>
  class GradientContraction
  {
  public:
    static constexpr unsigned int n_vertices = GeometryInfo<dim>::vertices_per_cell;

    /// Starts a cell of @p n_points points, each of which add_point() must
    /// add before add_to() (the rows are not zeroed).
    void
    reinit(const unsigned int n_points);

    /// Adds point @p q: its weight @p JxW, the gradients @p G of the
    /// vertices' functions (G[a], a < n_vertices) and the tensor @p A.
    void
    add_point(const unsigned int    q,
              const double          JxW,
              const Tensor<1, dim> *G,
              const double (&A)[dim][dim][dim][dim]);

    /// Adds K to @p matrix at the cell's dofs @p dof (dof[a][c]). K is
    /// symmetric where every A_q has the major symmetry, up to round-off.
    void
    add_to(const std::vector<std::array<unsigned int, dim>> &dof,
           FullMatrix<double>                               &matrix);

    /// Sets @p matrix, of the cell's dofs @p dof, to (K + K^T)/2: K where
    /// every A_q has the major symmetry, without K's round-off asymmetry
    /// (every entry written: no zeroing before, no symmetrizing after).
    void
    symmetric_part_into(const std::vector<std::array<unsigned int, dim>> &dof,
                        FullMatrix<double>                               &matrix);

  private:
    /// product = the weighted gradients' transpose times the gradients
    /// through the tensor.
    void
    multiply();

    /// Row q dim + J: JxW_q dN_a/dX_J in column a.
    FullMatrix<double> weighted_gradients;
    /// Row q dim + J: sum_L A_q[c][J][d][L] dN_b/dX_L in column
    /// (c dim + d) n_vertices + b.
    FullMatrix<double> gradients_through_tensor;
    /// K_(a,c),(b,d) in row a, column (c dim + d) n_vertices + b.
    FullMatrix<double> product;
    /// The points added since reinit().
    unsigned int n_added = 0;
  };
} // namespace FrictionalContact
