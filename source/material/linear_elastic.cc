#include <frictional_contact/base/plugins.h>
#include <frictional_contact/model/material.h>

namespace FrictionalContact
{
  namespace MaterialLaws
  {
    /**
     * Linear isotropic elasticity, sigma = 2 G dev(epsilon) + K theta I
     * (ElasticConstants): no history, a stiffness that does not change, so
     * that the body assembles K once and the solvers take it as it is.
     */
    template <int dim>
    class LinearElastic : public MaterialModel<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &)
      {}

      bool
      is_linear() const override
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
        // sigma = 2 G (epsilon - tr(epsilon) I / dim) + K theta I.
        const SymmetricTensor<2, dim> I = unit_symmetric_tensor<dim>();
        response.stress_by_strain =
          2. * elastic.shear_modulus * (identity_tensor<dim>() - outer_product(I, I) / dim);
        response.stress_by_volumetric_strain            = elastic.bulk_modulus * I;
        response.volumetric_stress_by_strain            = SymmetricTensor<2, dim>();
        response.volumetric_stress_by_volumetric_strain = elastic.bulk_modulus;
      }
    };

    FRICTIONAL_CONTACT_REGISTER_PLUGIN(
      MaterialModel,
      LinearElastic,
      "linear elastic",
      "Linear isotropic elasticity (Young's modulus, Poisson's ratio).")
  } // namespace MaterialLaws
} // namespace FrictionalContact
