#include <frictional_contact/base/input.h>
#include <frictional_contact/base/plugins.h>
#include <frictional_contact/material/material.h>

#include <cmath>

namespace FrictionalContact
{
  namespace MaterialLaws
  {
    /**
     * A neo-Hookean law of finite strain split into its isochoric and
     * volumetric parts, W = mu/2 (tr C_bar - 3) + U(theta) with C_bar =
     * J^-2/3 C and U = kappa/4 (theta^2 - 1 - 2 ln theta), in which theta
     * is the cell's mean volume ratio (the mean of J over the cell: the
     * mean-dilatation element of Simo, Taylor and Pister, equivalent to
     * their three-field Q1-P0 element), so that the volume constraint is
     * one per cell and the element does not lock as nu approaches 1/2.
     * mu and kappa (the 3D bulk modulus) come from Young's modulus and
     * Poisson's ratio; at small strain it is linear elasticity with them.
     * S = mu J^-2/3 (I - tr C / 3 C^-1) + U'(theta) J C^-1; the body adds
     * the coupling through theta (dS/dtheta = U''(theta) J C^-1, given as
     * the stress's derivative by the volumetric strain). In 2D (plane
     * strain) C_zz = 1: tr C counts it, and J = sqrt(det C). No history.
     */
    template <int dim>
    class NearlyIncompressibleNeoHookean : public HyperelasticLaw<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Volume ratio",
                          "cell mean",
                          Patterns::Anything(),
                          "theta in U(theta): 'cell mean', the mean of det F "
                          "over the cell (the mean-dilatation element, which "
                          "does not lock), or 'point', det F at each point of "
                          "the body's rule (the standard element, which locks as nu "
                          "approaches 1/2: for comparison).");
      }

      void
      parse_parameters(const BodyEntries &material, const BodyEntries &own) override
      {
        MaterialModel<dim>::parse_parameters(material, own);
        mu    = this->elastic().shear_modulus;
        kappa = this->elastic().bulk_modulus_3d;
        const std::string ratio = own.get("Volume ratio");
        if (ratio != "cell mean" && ratio != "point")
          Input::fail(own.path_of("Volume ratio"), ratio, "'cell mean' or 'point' is expected");
        cell_mean = ratio == "cell mean";
      }

      typename MaterialModel<dim>::VolumeRatio
      volume_ratio() const override
      {
        return cell_mean ? MaterialModel<dim>::VolumeRatio::cell_mean :
                           MaterialModel<dim>::VolumeRatio::point;
      }

      /// @p strain: the Green-Lagrange strain E; @p mean_volume_ratio:
      /// theta (the cell's mean of det F, or the point's).
      void
      evaluate(const SymmetricTensor<2, dim> &strain,
               const double                   mean_volume_ratio,
               const double *,
               const bool             with_tangent,
               MaterialResponse<dim> &response,
               double *) const override
      {
        const SymmetricTensor<2, dim> I      = unit_symmetric_tensor<dim>();
        const SymmetricTensor<2, dim> C      = I + 2. * strain;
        const SymmetricTensor<2, dim> C_inv  = invert(C);
        const double                  J      = std::sqrt(determinant(C));
        const double                  trace_C = trace(C) + (dim == 2 ? 1. : 0.);
        const double                  scale  = mu * std::pow(J, -2. / 3.);
        const double                  theta  = mean_volume_ratio;
        // U'(theta) and U''(theta).
        const double pressure = 0.5 * kappa * (theta - 1. / theta);
        const double stiffness = 0.5 * kappa * (1. + 1. / (theta * theta));
        response.stress = scale * (I - trace_C / 3. * C_inv) + pressure * J * C_inv;
        response.out_of_plane_stress =
          dim == 2 ? scale * (1. - trace_C / 3.) + pressure * J : 0.;
        response.volumetric_stress = pressure;
        response.plastic           = false;
        response.at_yield          = false;
        if (!with_tangent)
          return;
        // 2 dS/dC at fixed theta: 2 scale (-(I (x) C^-1 + C^-1 (x) I)/3 +
        // tr C/9 C^-1 (x) C^-1 + tr C/3 I_{C^-1}) + p J (C^-1 (x) C^-1 -
        // 2 I_{C^-1}), with I_{C^-1}_ijkl = (c_ik c_jl + c_il c_jk)/2.
        double c[dim][dim];
        this->plain_copy(C_inv, c);
        const double outer = 2. * scale * trace_C / 9. + pressure * J;
        const double cross = scale * trace_C / 3. - pressure * J;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            {
              Tensor<2, dim> &entries = response.stress_by_strain[i][j];
              for (unsigned int k = 0; k < dim; ++k)
                for (unsigned int l = 0; l < dim; ++l)
                  entries[k][l] =
                    -2. / 3. * scale * ((i == j ? c[k][l] : 0.) + (k == l ? c[i][j] : 0.)) +
                    outer * c[i][j] * c[k][l] +
                    cross * (c[i][k] * c[j][l] + c[i][l] * c[j][k]);
            }
        response.stress_by_volumetric_strain            = stiffness * J * C_inv;
        response.volumetric_stress_by_strain            = SymmetricTensor<2, dim>();
        response.volumetric_stress_by_volumetric_strain = stiffness;
      }

      std::string
      describe() const override
      {
        return "nearly incompressible neo-Hookean (mean dilatation), " +
               MaterialModel<dim>::describe();
      }

    private:
      double mu        = 0;
      double kappa     = 0;
      bool   cell_mean = true;
    };

    FRICTIONAL_CONTACT_REGISTER_PLUGIN(
      MaterialModel,
      NearlyIncompressibleNeoHookean,
      "nearly incompressible neo-Hookean",
      "A neo-Hookean law of finite strain split into isochoric and "
      "volumetric parts, the volume ratio averaged over each cell (the "
      "mean-dilatation element of Simo, Taylor and Pister, Q1-P0): it does "
      "not lock as Poisson's ratio approaches 1/2 (rubber: 0.499). Young's "
      "modulus and Poisson's ratio give its shear and bulk moduli; needs "
      "<Material/Kinematics> = finite strain.")
  } // namespace MaterialLaws
} // namespace FrictionalContact
