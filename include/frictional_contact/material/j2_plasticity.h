#pragma once

#include <frictional_contact/material/isotropic_hardening.h>
#include <frictional_contact/material/material.h>

namespace FrictionalContact
{
  namespace MaterialLaws
  {
    /// The symmetric 3D tensor of the history values @p values[0..5].
    inline SymmetricTensor<2, 3>
    read_history_tensor(const double *values)
    {
      SymmetricTensor<2, 3> t;
      for (unsigned int k = 0; k < SymmetricTensor<2, 3>::n_independent_components; ++k)
        t.access_raw_entry(k) = values[k];
      return t;
    }

    /// Writes @p t into the history values @p values[0..5].
    inline void
    write_history_tensor(const SymmetricTensor<2, 3> &t, double *values)
    {
      for (unsigned int k = 0; k < SymmetricTensor<2, 3>::n_independent_components; ++k)
        values[k] = t.access_raw_entry(k);
    }



    /**
     * The radial return of J2 plasticity from a trial stress deviator
     * beyond the back stress: the plastic multiplier Delta gamma (0 at an
     * elastic point), the flow direction n (unit, deviatoric) and the two
     * factors of the consistent tangent on the deviator, 2 mu theta P_dev -
     * 2 mu theta_bar n (x) n (Simo and Hughes, box 3.2): shear = mu theta,
     * flow = -2 mu theta_bar (mu and 0 at an elastic point).
     */
    struct RadialReturn
    {
      double                step     = 0;
      SymmetricTensor<2, 3> n;
      bool                  at_yield = false;
      double                shear    = 0;
      double                flow     = 0;
    };



    /**
     * J2 (von Mises) plasticity with associative flow,
     * isotropic hardening (linear, Voce or a measured flow curve:
     * IsotropicHardening) and linear kinematic (Prager) hardening,
     * integrated by the radial return (a scalar Newton solve where the
     * hardening is not linear) and linearised by its consistent tangent (Simo and
     * Taylor 1985; Simo and Hughes, Computational Inelasticity, box 3.2).
     * The return works on the 3D stress: in 2D (plane strain only) the
     * out-of-plane strain is zero and the plastic strain has its
     * out-of-plane part. With the B-bar element the volumetric strain is the
     * cell average: the 3D strain is dev(epsilon) + theta/3 I. A point keeps
     * its plastic strain (6), equivalent plastic strain alpha (1) and back
     * stress (6). step-42's parameters (sigma_0 bounds |dev sigma|, gamma the
     * hardening ratio) are accepted as they are: Yield stress measure =
     * deviator norm and Isotropic hardening ratio.
     *
     * At finite strain (<Material/Kinematics>) the same return works on the
     * logarithmic elastic strain: F = Fe Fp with isochoric plastic flow, the
     * Hencky law tau = 2 mu dev(eps_e) + J p I on the Kirchhoff stress, and
     * the exponential map that updates Cp^-1 (Weber and Anand 1990; Simo
     * 1992; Eterovic and Bathe 1990), in j2_finite_strain.cc. A point then
     * keeps Cp^-1 - I (6; zero at the start) and alpha (1), no back stress.
     */
    template <int dim>
    class J2Plasticity : public MaterialModel<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(const BodyEntries &material, const BodyEntries &own) override;

      bool
      is_linear() const override
      {
        return false;
      }

      bool
      flows_isochorically() const override
      {
        return true;
      }

      bool
      allows_finite_strain() const override
      {
        return true;
      }

      /// At finite strain the cell's mean volume ratio (the mean-dilatation
      /// element, Formulation = auto) or the point's (standard).
      typename MaterialModel<dim>::VolumeRatio
      volume_ratio() const override;

      /// Small strain: plastic strain (6), equivalent plastic strain (1),
      /// back stress (6). Finite strain: Cp^-1 - I (6), alpha (1).
      unsigned int
      n_history_values() const override
      {
        return this->elastic().finite_strain ? 7 : 13;
      }

      void
      evaluate(const SymmetricTensor<2, dim> &strain,
               const double                   volumetric_strain,
               const double                  *history,
               const bool                     with_tangent,
               MaterialResponse<dim>         &response,
               double                        *new_history) const override;

      double
      equivalent_plastic_strain(const double *history) const override
      {
        return history[6];
      }

      /// Small strain: eps_p. Finite strain: the logarithmic plastic
      /// strain ln(Cp) / 2 (on the reference configuration).
      SymmetricTensor<2, 3>
      plastic_strain(const double *history) const override;

      std::string
      describe() const override;

      /// The derivatives of the response for the 3D tangent kappa I (x) I +
      /// 2 mu P_dev + flow n (x) n of the strain, by the chain rule through
      /// the strain of the element.
      void
      tangent_of_strain(const double                 kappa,
                        const double                 mu,
                        const double                 flow,
                        const SymmetricTensor<2, 3> &n,
                        MaterialResponse<dim>       &response) const;

      /// The derivatives at an elastic point, the same everywhere.
      MaterialResponse<dim> elastic_response;

      /// The plastic multiplier Delta gamma of the radial return from a
      /// trial stress @p norm beyond the back stress, at the equivalent
      /// plastic strain @p alpha_before.
      double
      return_step(const double norm, const double alpha_before, const double mu) const;

      /// The radial return of the trial deviator @p relative (beyond the
      /// back stress) at the equivalent plastic strain @p alpha_before.
      RadialReturn
      radial_return(const SymmetricTensor<2, 3> &relative, const double alpha_before) const;

      /// evaluate() at finite strain: @p strain is E, @p volume_ratio theta.
      void
      evaluate_finite_strain(const SymmetricTensor<2, dim> &strain,
                             const double                   volume_ratio,
                             const double                  *history,
                             const bool                     with_tangent,
                             MaterialResponse<dim>         &response,
                             double                        *new_history) const;

      /// sigma_y(alpha): the uniaxial (von Mises) yield stress.
      IsotropicHardening hardening;
      /// H_kin: the slope of the uniaxial stress against the plastic
      /// strain that kinematic hardening adds.
      double kinematic_hardening = 0;
    };
  } // namespace MaterialLaws
} // namespace FrictionalContact
