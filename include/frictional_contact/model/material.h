#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>

#include <string>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * Linear isotropic elasticity: Young's modulus, Poisson's ratio and, in
   * 2D, plane stress or plane strain. Owns the stress-strain tensor.
   */
  template <int dim>
  class LinearElasticMaterial
  {
  public:
    /// Declares the entries of the subsection "Material".
    static void
    declare_parameters(ParameterHandler &prm);

    /// Reads the subsection "Material".
    explicit LinearElasticMaterial(ParameterHandler &prm);

    /// The fourth-order tensor C with sigma = C : epsilon.
    const SymmetricTensor<4, dim> &
    stress_strain_tensor() const
    {
      return stiffness;
    }

    /// "E = 1, nu = 0.3, plane stress"
    std::string
    describe() const;

    double youngs_modulus;
    double poissons_ratio;
    bool   plane_stress;

  private:
    SymmetricTensor<4, dim> stiffness;
  };
} // namespace FrictionalContact
