// The cells of an axisymmetric scene (x = r, y the axis): their strain
// with the hoop part, their 3D law, their force and tangent with the weight
// 2 pi r, and their averages for output. The element is the plane one's
// (body_response_cell.cc) with one more entry in every gradient: the
// virtual displacement gradient of dof (a, c) is e_c (x) Grad N_a, and
// for c = r also N_a / r in the hoop entry (3, 3).
#include <frictional_contact/model/axisymmetry.h>
#include <frictional_contact/model/body_response.h>

#include <algorithm>

namespace FrictionalContact
{
  namespace
  {
    /// A point of an axisymmetric cell: the gradients and values of the
    /// vertices' functions and the radius (dim is 2; the class compiles for
    /// 3 as the body's other members do, and serves no 3D cell).
    template <int dim>
    struct RevolvedPoint
    {
      const Tensor<1, dim> *gradients;
      const double       *values;
      double              radius;

      /// T : (virtual gradient of dof (a, c)), for a 3 x 3 tensor T.
      double
      against(const Tensor<2, 3> &T, const unsigned int a, const unsigned int c) const
      {
        double sum = T[c][0] * gradients[a][0] + T[c][1] * gradients[a][1];
        if (c == 0)
          sum += T[2][2] * values[a] / radius;
        return sum;
      }

      /// The divergence of the shape function of dof (a, c): its trace.
      double
      divergence(const unsigned int a, const unsigned int c) const
      {
        return gradients[a][c] + (c == 0 ? values[a] / radius : 0.);
      }
    };
  } // namespace



  template <int dim>
  void
  BodyResponse<dim>::evaluate_revolved_cell(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const Vector                                         &u_ghosted,
    const bool                                            with_tangent,
    CellScratch                                          &scratch,
    double                                               *new_history) const
  {
    using VolumeRatio            = typename MaterialModel<3>::VolumeRatio;
    const MaterialModel<3> &law  = materials.revolved(cell->material_id());
    const unsigned int n_vertices = scratch.dof.size();
    scratch.revolved                 = true;
    scratch.corner_points            = law.elastic().corner_points;
    scratch.finite_strain            = law.elastic().finite_strain;
    scratch.revolved_mean_dilatation = law.elastic().mean_dilatation;
    scratch.revolved_volume_ratio    = law.volume_ratio();

    FEValues<dim> &fe_values = scratch.fe_values();
    fe_values.reinit(typename Triangulation<dim>::cell_iterator(cell));
    scratch.n_points = fe_values.n_quadrature_points;
    ReferenceGradients<dim>::copy(fe_values, scratch.own_JxW.data(), scratch.own_gradients.data());
    scratch.JxW       = scratch.own_JxW.data();
    scratch.gradients = scratch.own_gradients.data();
    for (unsigned int q = 0; q < scratch.n_points; ++q)
      {
        scratch.radius[q] = fe_values.quadrature_point(q)[0];
        scratch.own_JxW[q] *= Axisymmetry::weight(fe_values.quadrature_point(q));
        for (unsigned int a = 0; a < n_vertices; ++a)
          scratch.values[q * n_vertices + a] = fe_values.shape_value(a, q);
      }
    cell->get_dof_values(u_ghosted, scratch.u);

    std::fill(scratch.mean_divergence.begin(), scratch.mean_divergence.end(), 0.);
    std::vector<SymmetricTensor<2, 3>> strain(scratch.n_points);
    double volume = 0, mean_dilatation = 0, mean_volume_ratio = 0;
    for (unsigned int q = 0; q < scratch.n_points; ++q)
      {
        const double        JxW = scratch.JxW[q];
        const RevolvedPoint<dim> point{scratch.gradients_at(q),
                                  &scratch.values[q * n_vertices],
                                  scratch.radius[q]};
        // The 3D displacement gradient: the in-plane one and u_r / r.
        Tensor<2, 3> gradient;
        for (unsigned int a = 0; a < n_vertices; ++a)
          for (unsigned int c = 0; c < dim; ++c)
            {
              const double u = scratch.u(scratch.dof[a][c]);
              for (unsigned int m = 0; m < dim; ++m)
                gradient[c][m] += u * point.gradients[a][m];
              if (c == 0)
                gradient[2][2] += u * point.values[a] / point.radius;
              scratch.mean_divergence[scratch.dof[a][c]] += point.divergence(a, c) * JxW;
            }
        volume += JxW;
        if (scratch.finite_strain)
          {
            Tensor<2, 3> &F = scratch.revolved_deformation[q];
            F               = unit_symmetric_tensor<3>() + gradient;
            strain[q]       = symmetrize(gradient) + 0.5 * symmetrize(transpose(gradient) * gradient);
            const double jacobian = scratch.jacobian[q] = determinant(F);
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

    const unsigned int n_history = law.n_history_values();
    const double      *committed = history.values(cell);
    for (unsigned int q = 0; q < scratch.n_points; ++q)
      if (!(scratch.jacobian[q] > 0))
        scratch.revolved_responses[q] = MaterialResponse<3>();
      else
        law.evaluate(strain[q],
                     scratch.revolved_volume_ratio == VolumeRatio::cell_mean ? mean_volume_ratio :
                     scratch.revolved_volume_ratio == VolumeRatio::point     ? scratch.jacobian[q] :
                     scratch.revolved_mean_dilatation                        ? mean_dilatation :
                                                                               trace(strain[q]),
                     committed == nullptr ? nullptr : committed + q * n_history,
                     with_tangent,
                     scratch.revolved_responses[q],
                     new_history == nullptr ? nullptr : new_history + q * n_history);
    // What the callers read of the plane responses.
    for (unsigned int q = 0; q < scratch.n_points; ++q)
      scratch.responses[q].plastic = scratch.revolved_responses[q].plastic;
  }



  template <int dim>
  void
  BodyResponse<dim>::revolved_force_and_tangent(const bool with_tangent, CellScratch &scratch) const
  {
    // As the plane kernels: at small strain f_i = int (sigma : Gamma_i +
    // (div_bar_i - div_i) pi) 2 pi r, with the law's D (and the B-bar
    // couplings); at finite strain f_i = int P : Gamma_i 2 pi R with
    // A = dP/dF = F C F + delta S, and the volume ratio's coupling h g^T.
    using VolumeRatio             = typename MaterialModel<3>::VolumeRatio;
    const unsigned int n_vertices = scratch.dof.size();
    const auto        &dof        = scratch.dof;
    const auto        &div_bar    = scratch.mean_divergence;
    const bool         finite     = scratch.finite_strain;
    const bool         b_bar      = !finite && scratch.revolved_mean_dilatation;
    const bool averages  = finite && scratch.revolved_volume_ratio != VolumeRatio::none;
    const bool pointwise = scratch.revolved_volume_ratio == VolumeRatio::point;
    constexpr unsigned int max_points = dim == 2 ? 9 : 27;
    constexpr unsigned int n_corners  = GeometryInfo<dim>::vertices_per_cell;
    const unsigned int     n_points   = scratch.n_points;
    const unsigned int     n_rows     = !averages ? 0 : pointwise ? n_points : 1;
    double h[max_points][n_corners][dim] = {};
    double g[max_points][n_corners][dim] = {};
    double volume                        = 0;
    scratch.force                        = 0;
    if (with_tangent)
      scratch.matrix = 0;
    for (unsigned int q = 0; q < n_points; ++q)
      {
        const double               JxW = scratch.JxW[q];
        const MaterialResponse<3> &r   = scratch.revolved_responses[q];
        const RevolvedPoint<dim>   point{scratch.gradients_at(q),
                                  &scratch.values[q * n_vertices],
                                  scratch.radius[q]};
        const Tensor<2, 3> F = finite ? scratch.revolved_deformation[q] :
                                        Tensor<2, 3>(unit_symmetric_tensor<3>());
        const Tensor<2, 3> S(r.stress);
        const Tensor<2, 3> P = finite ? F * S : S;
        for (unsigned int a = 0; a < n_vertices; ++a)
          for (unsigned int c = 0; c < dim; ++c)
            {
              double f = point.against(P, a, c);
              if (b_bar)
                f += (div_bar[dof[a][c]] - point.divergence(a, c)) * r.volumetric_stress;
              scratch.force(dof[a][c]) += f * JxW;
            }
        if (!with_tangent)
          continue;
        const Tensor<2, 3> by_theta(r.stress_by_volumetric_strain);
        if (averages && scratch.jacobian[q] > 0)
          {
            volume += JxW;
            const Tensor<2, 3> F_dS     = F * by_theta;
            const Tensor<2, 3> cofactor = scratch.jacobian[q] * transpose(invert(F));
            const unsigned int row      = pointwise ? q : 0;
            for (unsigned int a = 0; a < n_vertices; ++a)
              for (unsigned int c = 0; c < dim; ++c)
                {
                  h[row][a][c] += point.against(F_dS, a, c) * JxW;
                  g[row][a][c] += point.against(cofactor, a, c) * (pointwise ? 1. : JxW);
                }
          }
        // A_cJdL = F_cI C_IJKL F_dK + delta_cd S_JL, with C the law's
        // dS/dE and, where theta is the strain's own trace, d S/d theta (x) I.
        const bool   own_trace = !b_bar && !averages;
        double       A[3][3][3][3];
        for (unsigned int c = 0; c < 3; ++c)
          for (unsigned int J = 0; J < 3; ++J)
            for (unsigned int d = 0; d < 3; ++d)
              for (unsigned int L = 0; L < 3; ++L)
                {
                  double sum = finite && c == d ? S[J][L] : 0.;
                  for (unsigned int I = 0; I < 3; ++I)
                    for (unsigned int K = 0; K < 3; ++K)
                      sum += F[c][I] *
                             (r.stress_by_strain[I][J][K][L] +
                              (own_trace && K == L ? by_theta[I][J] : 0.)) *
                             F[d][K];
                  A[c][J][d][L] = sum;
                }
        for (unsigned int b = 0; b < n_vertices; ++b)
          for (unsigned int d = 0; d < dim; ++d)
            {
              // A : Gamma_(b, d).
              Tensor<2, 3> A_gamma;
              for (unsigned int c = 0; c < 3; ++c)
                for (unsigned int J = 0; J < 3; ++J)
                  A_gamma[c][J] = A[c][J][d][0] * point.gradients[b][0] +
                                  A[c][J][d][1] * point.gradients[b][1] +
                                  (d == 0 ? A[c][J][2][2] * point.values[b] / point.radius : 0.);
              for (unsigned int a = 0; a < n_vertices; ++a)
                for (unsigned int c = 0; c < dim; ++c)
                  scratch.matrix(dof[a][c], dof[b][d]) += point.against(A_gamma, a, c) * JxW;
            }
        if (!b_bar)
          continue;
        // K_ij += Gamma_i : c1 div_bar_j + (div_bar_i - div_i) (c2 :
        // Gamma_j + k div_bar_j).
        const Tensor<2, 3> by_strain(r.volumetric_stress_by_strain);
        for (unsigned int a = 0; a < n_vertices; ++a)
          for (unsigned int c = 0; c < dim; ++c)
            for (unsigned int b = 0; b < n_vertices; ++b)
              for (unsigned int d = 0; d < dim; ++d)
                scratch.matrix(dof[a][c], dof[b][d]) +=
                  (point.against(by_theta, a, c) * div_bar[dof[b][d]] +
                   (div_bar[dof[a][c]] - point.divergence(a, c)) *
                     (point.against(by_strain, b, d) +
                      r.volumetric_stress_by_volumetric_strain * div_bar[dof[b][d]])) *
                  JxW;
      }
    if (!with_tangent)
      return;
    FullMatrix<double> &matrix = scratch.matrix;
    for (unsigned int i = 0; i < matrix.m(); ++i)
      for (unsigned int j = i + 1; j < matrix.n(); ++j)
        matrix(i, j) = matrix(j, i) = 0.5 * (matrix(i, j) + matrix(j, i));
    for (unsigned int row = 0; row < n_rows; ++row)
      for (unsigned int a = 0; a < n_vertices; ++a)
        for (unsigned int c = 0; c < dim; ++c)
          for (unsigned int b = 0; b < n_vertices; ++b)
            for (unsigned int d = 0; d < dim; ++d)
              matrix(dof[a][c], dof[b][d]) +=
                h[row][a][c] * g[row][b][d] / (pointwise ? 1. : volume);
  }



  template <int dim>
  void
  BodyResponse<dim>::revolved_cell_state(const CellScratch       &scratch,
                                         const double            *committed,
                                         const types::material_id id,
                                         CellState<dim>          &state) const
  {
    // The Cauchy stress sigma = F S F^T / J at finite strain, averaged over
    // the deformed cell (of revolution); sigma_33 is the hoop stress.
    const MaterialModel<3> &law    = materials.revolved(id);
    double                  volume = 0, reference_volume = 0;
    for (unsigned int q = 0; q < scratch.n_points; ++q)
      {
        volume += scratch.jacobian[q] * scratch.JxW[q];
        reference_volume += scratch.JxW[q];
      }
    state.jacobian = volume / reference_volume;
    for (unsigned int q = 0; q < scratch.n_points; ++q)
      {
        const MaterialResponse<3> &r      = scratch.revolved_responses[q];
        const double               weight = scratch.jacobian[q] * scratch.JxW[q] / volume;
        SymmetricTensor<2, 3>      stress = r.stress;
        if (scratch.finite_strain)
          {
            const Tensor<2, 3> &F = scratch.revolved_deformation[q];
            stress = symmetrize(F * Tensor<2, 3>(r.stress) * transpose(F)) / scratch.jacobian[q];
          }
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = i; j < dim; ++j)
            state.stress[i][j] += weight * stress[i][j];
        state.out_of_plane_stress += weight * stress[2][2];
        state.mean_stress += weight * trace(stress) / 3.;
        state.von_mises_stress += weight * std::sqrt(1.5) * deviator(stress).norm();
        if (committed != nullptr)
          {
            const double *values = committed + q * law.n_history_values();
            state.equivalent_plastic_strain += weight * law.equivalent_plastic_strain(values);
            state.plastic_strain += weight * law.plastic_strain(values);
          }
        if (r.at_yield)
          state.yield_state = 2;
      }
    if (state.yield_state == 0 && state.equivalent_plastic_strain > 0)
      state.yield_state = 1;
  }

  // Each member apart: body_response.cc instantiates the class.
  template void
  BodyResponse<2>::evaluate_revolved_cell(const DoFHandler<2>::active_cell_iterator &,
                                          const Vector &,
                                          const bool,
                                          BodyResponse<2>::CellScratch &,
                                          double *) const;
  template void
  BodyResponse<2>::revolved_force_and_tangent(const bool, BodyResponse<2>::CellScratch &) const;
  template void
  BodyResponse<2>::revolved_cell_state(const BodyResponse<2>::CellScratch &,
                                       const double *,
                                       const types::material_id,
                                       CellState<2> &) const;
} // namespace FrictionalContact
