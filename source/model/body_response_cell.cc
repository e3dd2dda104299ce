// The cell kernels of BodyResponse: the internal force and tangent of one
// cell at small strain (standard or B-bar) and at finite strain, and the
// one line that stops a solve where a cell inverted.
#include <deal.II/base/mpi.h>

#include <frictional_contact/base/input.h>
#include <frictional_contact/model/body_response.h>

#include <algorithm>
#include <cmath>

namespace FrictionalContact
{
  namespace
  {
    /// sum_m g_m s_cm: a gradient against row @p c of a symmetric tensor.
    template <int dim>
    double
    against_row(const Tensor<1, dim> &g, const SymmetricTensor<2, dim> &s, const unsigned int c)
    {
      double sum = 0;
      for (unsigned int m = 0; m < dim; ++m)
        sum += g[m] * s[c][m];
      return sum;
    }


    /// Makes a cell matrix symmetric, the mean of it and its transpose: at
    /// each point the terms sum to B_i : D : B_j (B-bar: with the cell's
    /// mean divergence), symmetric where the law's D has the major
    /// symmetry, which its terms apart do not have.
    void
    make_symmetric(FullMatrix<double> &matrix)
    {
      for (unsigned int i = 0; i < matrix.m(); ++i)
        for (unsigned int j = i + 1; j < matrix.n(); ++j)
          matrix(i, j) = matrix(j, i) = 0.5 * (matrix(i, j) + matrix(j, i));
    }
  } // namespace



  template <int dim>
  void
  BodyResponse<dim>::cell_force_and_tangent(const bool   mean_dilatation,
                                            const bool   with_tangent,
                                            CellScratch &scratch) const
  {
    if constexpr (dim == 2)
      if (scratch.revolved)
        return revolved_force_and_tangent(with_tangent, scratch);
    if (scratch.finite_strain)
      return finite_strain_force_and_tangent(with_tangent, scratch);
    // The shape function of dof (a, c) is N_a e_c: its symmetric gradient
    // B has the entries grad N_a in row and column c, and its divergence
    // is d N_a / d x_c, so that the contractions reduce to sums over the
    // gradients.
    const unsigned int n_vertices = scratch.dof.size();
    const auto        &dof        = scratch.dof;
    const auto        &div_bar    = scratch.mean_divergence;
    scratch.force                 = 0;
    if (with_tangent)
      {
        // B-bar adds its terms at each point before the contraction's.
        if (mean_dilatation)
          scratch.matrix = 0;
        scratch.contraction.reinit(scratch.n_points);
      }
    double C[dim][dim][dim][dim];
    for (unsigned int q = 0; q < scratch.n_points; ++q)
      {
        const double                 JxW = scratch.JxW[q];
        const MaterialResponse<dim> &r   = scratch.responses[q];
        const Tensor<1, dim>        *G   = scratch.gradients_at(q);
        for (unsigned int a = 0; a < n_vertices; ++a)
          for (unsigned int c = 0; c < dim; ++c)
            {
              double f = against_row(G[a], r.stress, c);
              if (mean_dilatation)
                f += (div_bar[dof[a][c]] - G[a][c]) * r.volumetric_stress;
              scratch.force(dof[a][c]) += f * JxW;
            }
        if (!with_tangent)
          continue;
        // Standard element: d sigma = (C + c1 (x) I) : d epsilon. B-bar:
        // K_ij = B_i:C:B_j + B_i:c1 div_bar_j
        //        + (div_bar_i - div_i) (c2:B_j + k div_bar_j).
        for (unsigned int c = 0; c < dim; ++c)
          for (unsigned int m = 0; m < dim; ++m)
            for (unsigned int d = 0; d < dim; ++d)
              for (unsigned int n = 0; n < dim; ++n)
                C[c][m][d][n] = r.stress_by_strain[c][m][d][n] +
                                (mean_dilatation || d != n ?
                                   0. :
                                   r.stress_by_volumetric_strain[c][m]);
        scratch.contraction.add_point(q, JxW, G, C);
        if (!mean_dilatation)
          continue;
        double coupling[GeometryInfo<dim>::vertices_per_cell][dim];
        double volumetric[GeometryInfo<dim>::vertices_per_cell][dim];
        for (unsigned int a = 0; a < n_vertices; ++a)
          for (unsigned int c = 0; c < dim; ++c)
            {
              coupling[a][c]   = against_row(G[a], r.stress_by_volumetric_strain, c);
              volumetric[a][c] = against_row(G[a], r.volumetric_stress_by_strain, c) +
                                 r.volumetric_stress_by_volumetric_strain *
                                   div_bar[dof[a][c]];
            }
        for (unsigned int a = 0; a < n_vertices; ++a)
          for (unsigned int c = 0; c < dim; ++c)
            for (unsigned int b = 0; b < n_vertices; ++b)
              for (unsigned int d = 0; d < dim; ++d)
                scratch.matrix(dof[a][c], dof[b][d]) +=
                  (coupling[a][c] * div_bar[dof[b][d]] +
                   (div_bar[dof[a][c]] - G[a][c]) * volumetric[b][d]) *
                  JxW;
      }
    if (with_tangent && mean_dilatation)
      {
        scratch.contraction.add_to(dof, scratch.matrix);
        make_symmetric(scratch.matrix);
      }
    else if (with_tangent)
      scratch.contraction.symmetric_part_into(dof, scratch.matrix);
  }



  template <int dim>
  void
  BodyResponse<dim>::finite_strain_force_and_tangent(const bool   with_tangent,
                                                     CellScratch &scratch) const
  {
    // The shape function of dof (a, c) is N_a e_c, its gradient e_c (x)
    // Grad N_a: the force is (F S)_cJ dN_a/dX_J, the material part of the
    // matrix dN_a/dX_J F_cI C_IJKL F_dK dN_b/dX_L, the geometric part
    // delta_cd Grad N_a . S Grad N_b. A law of a volume ratio theta adds
    // the coupling through it: for the cell's mean, h_ac g_bd / V with
    // h_ac = int (F dS/dtheta)_cJ dN_a/dX_J and g_bd = int J (F^-T Grad
    // N_b)_d (V d theta/du_bd); for the point's J, the same products at
    // each point.
    using VolumeRatio             = typename MaterialModel<dim>::VolumeRatio;
    const unsigned int n_vertices = scratch.dof.size();
    const auto        &dof        = scratch.dof;
    const bool         averages   = scratch.volume_ratio != VolumeRatio::none;
    const bool         pointwise  = scratch.volume_ratio == VolumeRatio::point;
    scratch.force                 = 0;
    if (with_tangent)
      scratch.contraction.reinit(scratch.n_points);
    // At most the 3^dim Gauss-Lobatto points; rows of h and g: one per
    // point for the point's volume ratio, one for the cell's mean.
    constexpr unsigned int max_points = dim == 2 ? 9 : 27;
    const unsigned int     n_points   = scratch.n_points;
    const unsigned int     n_rows     = !averages ? 0 : pointwise ? n_points : 1;
    AssertIndexRange(n_points, max_points + 1);
    double h[max_points][GeometryInfo<dim>::vertices_per_cell][dim];
    double g[max_points][GeometryInfo<dim>::vertices_per_cell][dim];
    std::fill(&h[0][0][0], &h[0][0][0] + n_rows * n_vertices * dim, 0.);
    std::fill(&g[0][0][0], &g[0][0][0] + n_rows * n_vertices * dim, 0.);
    double volume = 0;
    for (unsigned int q = 0; q < n_points; ++q)
      {
        const double                 JxW = scratch.JxW[q];
        const MaterialResponse<dim> &r   = scratch.responses[q];
        const Tensor<1, dim>        *G   = scratch.gradients_at(q);
        const Tensor<2, dim>        &F   = scratch.deformation_gradient[q];
        const Tensor<2, dim>         S(r.stress);
        const Tensor<2, dim>         P = F * S;
        for (unsigned int a = 0; a < n_vertices; ++a)
          for (unsigned int c = 0; c < dim; ++c)
            scratch.force(dof[a][c]) += (P[c] * G[a]) * JxW;
        if (!with_tangent)
          continue;
        if (averages && scratch.jacobian[q] > 0)
          {
            volume += JxW;
            const Tensor<2, dim> F_dS = F * Tensor<2, dim>(r.stress_by_volumetric_strain);
            const Tensor<2, dim> cofactor = scratch.jacobian[q] * transpose(invert(F));
            // For the cell's mean, every point adds to the first row.
            const unsigned int row = pointwise ? q : 0;
            for (unsigned int a = 0; a < n_vertices; ++a)
              for (unsigned int c = 0; c < dim; ++c)
                {
                  h[row][a][c] += (F_dS[c] * G[a]) * JxW;
                  g[row][a][c] += (cofactor[c] * G[a]) * (pointwise ? 1. : JxW);
                }
          }
        // The first elasticity tensor A = dP/dF: A_cJdL = F_cI C_IJKL F_dK +
        // delta_cd S_JL, with C the law's dS/dE (its volumetric part
        // c1 (x) I); the entry of (a, c), (b, d) is
        // dN_a/dX_J A_cJdL dN_b/dX_L (GradientContraction).
        const Tensor<2, dim> volumetric_part =
          averages ? Tensor<2, dim>() : Tensor<2, dim>(r.stress_by_volumetric_strain);
        double CF[dim][dim][dim][dim]; // CF[I][J][d][L] = C_IJKL F_dK
        for (unsigned int I = 0; I < dim; ++I)
          for (unsigned int J = 0; J < dim; ++J)
            for (unsigned int d = 0; d < dim; ++d)
              for (unsigned int L = 0; L < dim; ++L)
                {
                  double sum = volumetric_part[I][J] * F[d][L];
                  for (unsigned int K = 0; K < dim; ++K)
                    sum += r.stress_by_strain[I][J][K][L] * F[d][K];
                  CF[I][J][d][L] = sum;
                }
        double A[dim][dim][dim][dim];
        for (unsigned int c = 0; c < dim; ++c)
          for (unsigned int J = 0; J < dim; ++J)
            for (unsigned int d = 0; d < dim; ++d)
              for (unsigned int L = 0; L < dim; ++L)
                {
                  double sum = c == d ? S[J][L] : 0.;
                  for (unsigned int I = 0; I < dim; ++I)
                    sum += F[c][I] * CF[I][J][d][L];
                  A[c][J][d][L] = sum;
                }
        scratch.contraction.add_point(q, JxW, G, A);
      }
    if (with_tangent)
      scratch.contraction.symmetric_part_into(dof, scratch.matrix);
    if (with_tangent && averages)
      for (unsigned int row = 0; row < n_rows; ++row)
        for (unsigned int a = 0; a < n_vertices; ++a)
          for (unsigned int c = 0; c < dim; ++c)
            for (unsigned int b = 0; b < n_vertices; ++b)
              for (unsigned int d = 0; d < dim; ++d)
                scratch.matrix(dof[a][c], dof[b][d]) +=
                  h[row][a][c] * g[row][b][d] / (pointwise ? 1. : volume);
  }



  template <int dim>
  void
  BodyResponse<dim>::refuse_inverted_cells(const CellScratch &scratch) const
  {
    const PlacedMinimum<dim> smallest =
      scratch.smallest_jacobian.over_ranks(body.get_mpi_communicator());
    if (smallest.value > 0)
      return;
    throw InvertedCell("the cell at " + smallest.place() +
                       " is inverted (det F = " + Input::to_text(smallest.value) +
                       " <= 0): take smaller increments, or let them be cut "
                       "(<Loading/On failure> = cut increment)");
  }

  // Each member apart: body_response.cc instantiates the class (a class
  // instantiation here would define its other members twice).
  template void
  BodyResponse<2>::cell_force_and_tangent(const bool,
                                           const bool,
                                           BodyResponse<2>::CellScratch &) const;
  template void
  BodyResponse<2>::finite_strain_force_and_tangent(const bool,
                                                    BodyResponse<2>::CellScratch &) const;
  template void
  BodyResponse<2>::refuse_inverted_cells(const BodyResponse<2>::CellScratch &) const;
  template void
  BodyResponse<3>::cell_force_and_tangent(const bool,
                                           const bool,
                                           BodyResponse<3>::CellScratch &) const;
  template void
  BodyResponse<3>::finite_strain_force_and_tangent(const bool,
                                                    BodyResponse<3>::CellScratch &) const;
  template void
  BodyResponse<3>::refuse_inverted_cells(const BodyResponse<3>::CellScratch &) const;
} // namespace FrictionalContact
