// J2 plasticity at finite strain: the multiplicative split F = Fe Fp with
// isochoric plastic flow, the Hencky (logarithmic) elastic law on the
// Kirchhoff stress and the exponential map, which makes the return the
// small-strain radial return on the logarithmic elastic strain (Weber and
// Anand 1990; Eterovic and Bathe 1990; Simo 1992; de Souza Neto, Peric and
// Owen, Computational Methods for Plasticity, ch. 14). doc/formulation.md
// says why this one and writes it out.
#include <frictional_contact/material/j2_plasticity.h>
#include <frictional_contact/material/spectral_decomposition.h>

#include <cmath>

namespace FrictionalContact
{
  namespace MaterialLaws
  {
    namespace
    {
      /// (x_a + x_b) (ln x_a - ln x_b) / (x_a - x_b), 2 where x_a = x_b:
      /// the derivative of ln(b) in the direction d b + b d, in the
      /// eigenbasis of b (the Daleckii-Krein formula), as 2 atanh(t) / t
      /// with t = (x_a - x_b) / (x_a + x_b), which stays exact as t -> 0.
      double
      logarithm_factor(const double x_a, const double x_b)
      {
        const double t = (x_a - x_b) / (x_a + x_b);
        if (std::abs(t) < 1e-5)
          return 2. * (1. + t * t / 3.);
        return 2. * std::atanh(t) / t;
      }
    } // namespace



    template <int dim>
    void
    J2Plasticity<dim>::evaluate_finite_strain(const SymmetricTensor<2, dim> &strain,
                                              const double           volume_ratio,
                                              const double          *history,
                                              const bool             with_tangent,
                                              MaterialResponse<dim> &response,
                                              double                *new_history) const
    {
      using Symmetric3 = SymmetricTensor<2, 3>;
      const double     mu    = this->elastic().shear_modulus;
      const double     kappa = this->elastic().bulk_modulus_3d;
      const Symmetric3 I     = unit_symmetric_tensor<3>();

      // C = I + 2 E (C_zz = 1 in plane strain) and its stretch U: S depends
      // on C only, so F = U serves (any F = R U gives the same S).
      Symmetric3 C = I;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          C[i][j] += 2. * strain[i][j];
      const SpectralDecomposition right(C);
      const Symmetric3 U     = right.map([](const double x) { return std::sqrt(x); });
      const Symmetric3 U_inv = right.map([](const double x) { return 1. / std::sqrt(x); });
      const double     J     = std::sqrt(right.values[0] * right.values[1] * right.values[2]);

      // The trial elastic left Cauchy-Green tensor b_e = F Cp^-1 F^T, its
      // logarithmic strain ln(b_e) / 2 and the radial return of its
      // deviator's Kirchhoff stress.
      // A point that never flowed has Cp = I: its trial b_e is C, whose
      // decomposition is at hand.
      const double                 alpha_before = history[6];
      const Symmetric3             plastic_history = read_history_tensor(history);
      const SpectralDecomposition  elastic_left =
        plastic_history.norm() == 0. ? right :
                                       SpectralDecomposition(congruence(U, I + plastic_history));
      const Symmetric3             trial_strain =
        elastic_left.map([](const double x) { return 0.5 * std::log(x); });
      const Symmetric3   trial = 2. * mu * deviator(trial_strain);
      const RadialReturn flow  = radial_return(trial, alpha_before);
      response.plastic         = flow.step > 0;
      response.at_yield        = flow.at_yield;

      // tau = 2 mu dev(eps_e) + J p I with p = U'(theta), U = kappa/2 (ln
      // theta)^2 (the Hencky volumetric energy): theta the cell's mean
      // volume ratio or the point's J (then J p = kappa ln J). S = F^-1 tau
      // F^-T.
      const double     theta    = volume_ratio;
      const double     pressure = kappa * std::log(theta) / theta;
      const double     pressure_slope = kappa * (1. - std::log(theta)) / (theta * theta);
      const Symmetric3 tau      = trial - 2. * mu * flow.step * flow.n + J * pressure * I;
      const Symmetric3 S        = congruence(U_inv, tau);
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          response.stress[i][j] = S[i][j];
      response.out_of_plane_stress = dim == 2 ? S[2][2] : 0.;
      response.volumetric_stress   = pressure;

      if (new_history != nullptr)
        {
          // The exponential map: b_e = exp(2 (eps_e_trial - Delta gamma n)),
          // coaxial with the trial b_e; Cp^-1 = F^-1 b_e F^-T.
          const Symmetric3      n_principal = elastic_left.to_eigenbasis(flow.n);
          std::array<double, 3> b;
          for (unsigned int a = 0; a < 3; ++a)
            b[a] = elastic_left.values[a] *
                   std::exp(-2. * flow.step * n_principal[a][a]);
          const Symmetric3 elastic_b = elastic_left.from_eigenbasis_diagonal(b);
          write_history_tensor(congruence(U_inv, elastic_b) - I, new_history);
          new_history[6] = alpha_before + std::sqrt(2. / 3.) * flow.step;
        }
      if (!with_tangent)
        return;

      // dS/dE in the direction H: with d = F^-T H F^-1 (the rate of
      // deformation that goes with it), the trial b_e moves by d b_e + b_e
      // d, the logarithmic strain by half its derivative of ln (in the
      // eigenbasis of b_e: d_ab (b_a + b_b) ln[b_a, b_b] / 2), tau by the
      // consistent tangent on it plus p dJ I = J p tr(d) I; the Lie
      // derivative of tau is that minus d tau + tau d, and dS = F^-1 L(tau)
      // F^-T. All of it in the eigenbasis Q of b_e, where tau and n are
      // diagonal (isotropic functions of b_e): with W = U^-1 Q, d has the
      // components W^T H W there and dS = W L W^T.
      double factor[3][3];
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int b = 0; b < 3; ++b)
          factor[a][b] = 0.5 * logarithm_factor(elastic_left.values[a], elastic_left.values[b]);
      const Tensor<2, 3> W           = Tensor<2, 3>(U_inv) * elastic_left.vectors;
      const Symmetric3   tau_in_eigenbasis = elastic_left.to_eigenbasis(tau);
      const Symmetric3   n_in_eigenbasis   = elastic_left.to_eigenbasis(flow.n);
      for (unsigned int k = 0; k < dim; ++k)
        for (unsigned int l = k; l < dim; ++l)
          {
            // d = W^T H W for H = (e_k (x) e_l + e_l (x) e_k) / 2.
            Tensor<2, 3> d;
            for (unsigned int a = 0; a < 3; ++a)
              for (unsigned int b = 0; b < 3; ++b)
                d[a][b] = 0.5 * (W[k][a] * W[l][b] + W[l][a] * W[k][b]);
            Tensor<2, 3> strain_change;
            for (unsigned int a = 0; a < 3; ++a)
              for (unsigned int b = 0; b < 3; ++b)
                strain_change[a][b] = factor[a][b] * d[a][b];
            const double volume_change = trace(strain_change) / 3.;
            double       flow_part     = 0;
            for (unsigned int a = 0; a < 3; ++a)
              flow_part += n_in_eigenbasis[a][a] * (strain_change[a][a] - volume_change);
            flow_part *= flow.flow;
            const double pressure_part = J * pressure * trace(d);
            Tensor<2, 3> lie_derivative;
            for (unsigned int a = 0; a < 3; ++a)
              for (unsigned int b = 0; b < 3; ++b)
                lie_derivative[a][b] =
                  2. * flow.shear * (strain_change[a][b] - (a == b ? volume_change : 0.)) +
                  (a == b ? flow_part * n_in_eigenbasis[a][a] + pressure_part : 0.) -
                  d[a][b] * (tau_in_eigenbasis[a][a] + tau_in_eigenbasis[b][b]);
            const Tensor<2, 3> S_change = W * lie_derivative * transpose(W);
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                {
                  response.stress_by_strain[i][j][k][l] = S_change[i][j];
                  response.stress_by_strain[i][j][l][k] = S_change[i][j];
                }
          }
      // dS/dtheta = U''(theta) J C^-1; theta enters nothing else.
      const Symmetric3 C_inv = right.map([](const double x) { return 1. / x; });
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          response.stress_by_volumetric_strain[i][j] = pressure_slope * J * C_inv[i][j];
      response.volumetric_stress_by_strain            = SymmetricTensor<2, dim>();
      response.volumetric_stress_by_volumetric_strain = pressure_slope;
    }

    template void
    J2Plasticity<2>::evaluate_finite_strain(const SymmetricTensor<2, 2> &,
                                            const double,
                                            const double *,
                                            const bool,
                                            MaterialResponse<2> &,
                                            double *) const;
    template void
    J2Plasticity<3>::evaluate_finite_strain(const SymmetricTensor<2, 3> &,
                                            const double,
                                            const double *,
                                            const bool,
                                            MaterialResponse<3> &,
                                            double *) const;
  } // namespace MaterialLaws
} // namespace FrictionalContact
