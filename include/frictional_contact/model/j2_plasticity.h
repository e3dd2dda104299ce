#pragma once

#include <frictional_contact/model/isotropic_hardening.h>
#include <frictional_contact/model/material.h>

namespace FrictionalContact
{
  namespace MaterialLaws
  {
    /**
     * Small-strain J2 (von Mises) plasticity with associative flow,
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

      /// Plastic strain (6), equivalent plastic strain (1), back stress (6).
      unsigned int
      n_history_values() const override
      {
        return 13;
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

      /// sigma_y(alpha): the uniaxial (von Mises) yield stress.
      IsotropicHardening hardening;
      /// H_kin: the slope of the uniaxial stress against the plastic
      /// strain that kinematic hardening adds.
      double kinematic_hardening = 0;
    };
  } // namespace MaterialLaws
} // namespace FrictionalContact
