#include <frictional_contact/base/plugins.h>
#include <frictional_contact/material/material.h>

namespace FrictionalContact
{
  namespace MaterialLaws
  {
    /**
     * Linear isotropic elasticity, sigma = 2 G dev(epsilon) + K theta I
     * (ElasticConstants): no history, a stiffness that does not change, so
     * that the body assembles K once and the solvers take it as it is. At
     * finite strain the same law of S and E: St. Venant-Kirchhoff.
     */
    template <int dim>
    class LinearElastic : public MaterialModel<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &)
      {}

      void
      parse_parameters(const BodyEntries &material, const BodyEntries &own) override
      {
        MaterialModel<dim>::parse_parameters(material, own);
        // sigma = 2 G (epsilon - tr(epsilon) I / dim) + K theta I.
        const ElasticConstants<dim> &elastic = this->elastic();
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int l = 0; l < dim; ++l)
                tangent[i][j][k][l] =
                  elastic.shear_modulus * ((i == k && j == l ? 1. : 0.) +
                                           (i == l && j == k ? 1. : 0.) -
                                           (i == j && k == l ? 2. / dim : 0.));
      }

      bool
      is_linear() const override
      {
        return true;
      }

      /// At finite strain, S = C : E: the St. Venant-Kirchhoff law.
      bool
      allows_finite_strain() const override
      {
        return true;
      }

      void
      evaluate(const SymmetricTensor<2, dim> &strain,
               const double                   volumetric_strain,
               const double *,
               const bool             with_tangent,
               MaterialResponse<dim> &response,
               double *) const override
      {
        const ElasticConstants<dim> &elastic = this->elastic();
        response.stress              = elastic.stress(strain, volumetric_strain);
        response.volumetric_stress   = elastic.bulk_modulus * volumetric_strain;
        response.out_of_plane_stress = elastic.out_of_plane_stress(response.stress);
        response.plastic             = false;
        response.at_yield            = false;
        if (!with_tangent)
          return;
        response.stress_by_strain = tangent;
        response.stress_by_volumetric_strain =
          elastic.bulk_modulus * unit_symmetric_tensor<dim>();
        response.volumetric_stress_by_strain            = SymmetricTensor<2, dim>();
        response.volumetric_stress_by_volumetric_strain = elastic.bulk_modulus;
      }

    private:
      /// d sigma / d epsilon, the same at every point.
      Tensor<4, dim> tangent;
    };

    FRICTIONAL_CONTACT_REGISTER_PLUGIN(
      MaterialModel,
      LinearElastic,
      "linear elastic",
      "Linear isotropic elasticity (Young's modulus, Poisson's ratio).")
  } // namespace MaterialLaws
} // namespace FrictionalContact
