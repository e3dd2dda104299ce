#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/types.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * Linear isotropic elasticity: Young's modulus, Poisson's ratio, in 2D
   * plane stress or plane strain, and the element formulation that carries
   * the volumetric strain (the standard Q1 element, or the mean-dilatation
   * B-bar element that does not lock as nu approaches 1/2). Owns the
   * stress-strain tensor and its split into shear and bulk parts.
   */
  template <int dim>
  class LinearElasticMaterial
  {
  public:
    /// Declares the entries of the subsection "Material".
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Reads the subsection "Material" for the body @p body of the bodies
     * @p all_bodies: an entry is one value for every body, or 'body:
     * value; other body: value'.
     */
    LinearElasticMaterial(ParameterHandler               &prm,
                          const std::string              &body,
                          const std::vector<std::string> &all_bodies);

    /// The fourth-order tensor C with sigma = C : epsilon (of the standard
    /// element).
    const SymmetricTensor<4, dim> &
    stress_strain_tensor() const
    {
      return stiffness;
    }

    /**
     * The stress of a strain @p strain whose volumetric part (its trace)
     * is replaced by @p volumetric_strain: the cell average of the trace
     * for the B-bar element, the trace itself for the standard one.
     * sigma = 2 G dev(epsilon) + K theta I, with the deviator and the
     * bulk modulus K of dim dimensions (the in-plane ones in 2D).
     */
    SymmetricTensor<2, dim>
    stress(const SymmetricTensor<2, dim> &strain,
           const double                   volumetric_strain) const;

    /// The out-of-plane normal stress of plane strain (zero in plane
    /// stress) for the in-plane stress @p stress.
    double
    out_of_plane_stress(const SymmetricTensor<2, dim> &stress) const;

    /// The mean stress trace(sigma)/3 (of the 3D stress, in 2D with the
    /// out-of-plane stress) for a volumetric strain @p volumetric_strain.
    double
    mean_stress(const double volumetric_strain) const;

    /// "E = 1, nu = 0.3, plane stress" (and ", B-bar element" when used)
    std::string
    describe() const;

    /**
     * A warning line when the standard element is forced on a nearly
     * incompressible material (it locks); empty otherwise.
     */
    std::string
    locking_warning() const;

    double youngs_modulus;
    double poissons_ratio;
    bool   plane_stress;
    /// Whether the mean-dilatation (B-bar) element is used.
    bool   mean_dilatation;
    /// G: the shear modulus.
    double shear_modulus;
    /// K: the bulk modulus of dim-dimensional elasticity (lambda + 2 G / dim,
    /// with the plane-stress lambda in 2D plane stress).
    double bulk_modulus;

    /// Above this Poisson's ratio, 'auto' picks the B-bar element.
    static constexpr double locking_threshold = 0.45;

  private:
    SymmetricTensor<4, dim> stiffness;
    /// Whether the user forced the standard element.
    bool standard_forced;
  };



  /**
   * The material of each body of the scene (bodies are the material ids of
   * the mesh, named by the geometry), read from the subsection "Material".
   * Owns one LinearElasticMaterial per body.
   */
  template <int dim>
  class Materials
  {
  public:
    /// Reads the subsection "Material" for the bodies @p bodies (name ->
    /// material id).
    Materials(ParameterHandler                                &prm,
              const std::map<std::string, types::material_id> &bodies);

    /// The material of the cells with material id @p id.
    const LinearElasticMaterial<dim> &
    of(const types::material_id id) const;

    /// Whether some body uses the B-bar element.
    bool
    any_mean_dilatation() const;

    /// "E = 1, nu = 0.3" for one body, "base: E = ...; block: ..." for more.
    std::string
    describe() const;

    /// The locking warnings of the bodies, one line each.
    std::vector<std::string>
    locking_warnings() const;

  private:
    std::map<types::material_id, std::unique_ptr<LinearElasticMaterial<dim>>>
                                                materials;
    std::map<types::material_id, std::string> names;
  };
} // namespace FrictionalContact
