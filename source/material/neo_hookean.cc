#include <frictional_contact/base/plugins.h>
#include <frictional_contact/material/material.h>

#include <cmath>

namespace FrictionalContact
{
  namespace MaterialLaws
  {
    /**
     * The compressible neo-Hookean law of finite strain, W(C) = mu/2 (tr C
     * - 3) - mu ln J + lambda/2 (ln J)^2 (Bonet and Wood, Nonlinear
     * Continuum Mechanics, 6.4.3), with mu and lambda from Young's modulus
     * and Poisson's ratio (its small-strain limit is linear elasticity with
     * them): S = mu (I - C^-1) + lambda ln J C^-1 and dS/dE = lambda C^-1
     * (x) C^-1 + 2 (mu - lambda ln J) I_{C^-1}. In 2D (plane strain) C_zz =
     * 1, so that J = sqrt(det C) of the in-plane C and S_zz = lambda ln J.
     * No history.
     */
    template <int dim>
    class NeoHookean : public HyperelasticLaw<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &)
      {}

      void
      parse_parameters(const BodyEntries &material, const BodyEntries &own) override
      {
        MaterialModel<dim>::parse_parameters(material, own);
        mu     = this->elastic().shear_modulus;
        lambda = this->elastic().bulk_modulus_3d - 2. / 3. * mu;
      }

      /// @p strain: the Green-Lagrange strain E = (C - I)/2, whose
      /// determinant the body has checked (det F > 0).
      void
      evaluate(const SymmetricTensor<2, dim> &strain,
               const double,
               const double *,
               const bool             with_tangent,
               MaterialResponse<dim> &response,
               double *) const override
      {
        const SymmetricTensor<2, dim> I        = unit_symmetric_tensor<dim>();
        const SymmetricTensor<2, dim> C        = I + 2. * strain;
        const SymmetricTensor<2, dim> C_inv    = invert(C);
        const double                  log_J    = 0.5 * std::log(determinant(C));
        response.stress                        = mu * (I - C_inv) + lambda * log_J * C_inv;
        response.out_of_plane_stress           = dim == 2 ? lambda * log_J : 0.;
        response.volumetric_stress             = 0;
        response.plastic                       = false;
        response.at_yield                      = false;
        if (!with_tangent)
          return;
        const double shear = mu - lambda * log_J;
        double c[dim][dim];
        this->plain_copy(C_inv, c);
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            {
              Tensor<2, dim> &entries = response.stress_by_strain[i][j];
              for (unsigned int k = 0; k < dim; ++k)
                for (unsigned int l = 0; l < dim; ++l)
                  entries[k][l] = lambda * c[i][j] * c[k][l] +
                                  shear * (c[i][k] * c[j][l] + c[i][l] * c[j][k]);
            }
        response.stress_by_volumetric_strain            = SymmetricTensor<2, dim>();
        response.volumetric_stress_by_strain            = SymmetricTensor<2, dim>();
        response.volumetric_stress_by_volumetric_strain = 0;
      }

      std::string
      describe() const override
      {
        return "neo-Hookean, " + MaterialModel<dim>::describe();
      }

    private:
      double mu     = 0;
      double lambda = 0;
    };

    FRICTIONAL_CONTACT_REGISTER_PLUGIN(
      MaterialModel,
      NeoHookean,
      "neo-Hookean",
      "The compressible neo-Hookean law of finite strain (Young's modulus "
      "and Poisson's ratio give its shear modulus and Lame constant); needs "
      "<Material/Kinematics> = finite strain.")
  } // namespace MaterialLaws
} // namespace FrictionalContact
