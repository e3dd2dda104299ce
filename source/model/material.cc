#include <frictional_contact/base/input.h>
#include <frictional_contact/model/material.h>

namespace FrictionalContact
{
  template <int dim>
  void
  LinearElasticMaterial<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    prm.declare_entry("Young's modulus",
                      "1",
                      Patterns::Double(0.),
                      "Young's modulus E of the body (force/area, > 0).");
    prm.declare_entry("Poisson's ratio",
                      "0.3",
                      Patterns::Double(-1., 0.5),
                      "Poisson's ratio nu of the body, in (-1, 0.5).");
    prm.declare_entry("Two-dimensional model",
                      "plane strain",
                      Patterns::Selection("plane strain|plane stress"),
                      "How a 2D computation models the third direction: "
                      "plane strain (a long body, the usual default) or "
                      "plane stress (a thin plate, as in Kanno's example I). "
                      "Ignored in 3D.");
    prm.declare_entry(
      "Formulation",
      "auto",
      Patterns::Selection("auto|standard|B-bar"),
      "The element: 'standard' Q1, or 'B-bar', the mean-dilatation Q1 "
      "element (Hughes; the volumetric strain replaced by its cell average, "
      "which is Q1-P0 with the pressure condensed), which does not lock "
      "when the material is nearly incompressible. 'auto' uses B-bar when "
      "Poisson's ratio exceeds 0.45 (in 3D and plane strain; plane stress "
      "does not lock) and the standard element otherwise.");
    prm.leave_subsection();
  }



  template <int dim>
  LinearElasticMaterial<dim>::LinearElasticMaterial(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    youngs_modulus = prm.get_double("Young's modulus");
    poissons_ratio = prm.get_double("Poisson's ratio");
    plane_stress   = dim == 2 && prm.get("Two-dimensional model") == "plane stress";
    const std::string formulation = prm.get("Formulation");
    prm.leave_subsection();

    if (!(youngs_modulus > 0))
      Input::fail("Material/Young's modulus",
                  Input::to_text(youngs_modulus),
                  "a positive number is expected");
    if (!(poissons_ratio > -1 && poissons_ratio < 0.5))
      Input::fail("Material/Poisson's ratio",
                  Input::to_text(poissons_ratio),
                  "a number strictly between -1 and 0.5 is expected");

    const bool locks = !plane_stress && poissons_ratio > locking_threshold;
    mean_dilatation  = formulation == "B-bar" || (formulation == "auto" && locks);
    standard_forced  = formulation == "standard";

    const double mu = youngs_modulus / (2. * (1. + poissons_ratio));
    double       lambda = youngs_modulus * poissons_ratio /
                    ((1. + poissons_ratio) * (1. - 2. * poissons_ratio));
    if (plane_stress)
      lambda = 2. * lambda * mu / (lambda + 2. * mu);
    shear_modulus = mu;
    bulk_modulus  = lambda + 2. * mu / dim;

    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int l = 0; l < dim; ++l)
            stiffness[i][j][k][l] =
              (i == j && k == l ? lambda : 0.) +
              (i == k && j == l ? mu : 0.) + (i == l && j == k ? mu : 0.);
  }



  template <int dim>
  SymmetricTensor<2, dim>
  LinearElasticMaterial<dim>::stress(const SymmetricTensor<2, dim> &strain,
                                     const double volumetric_strain) const
  {
    return 2. * shear_modulus * deviator(strain) +
           bulk_modulus * volumetric_strain * unit_symmetric_tensor<dim>();
  }



  template <int dim>
  double
  LinearElasticMaterial<dim>::out_of_plane_stress(
    const SymmetricTensor<2, dim> &stress) const
  {
    // Plane strain: sigma_zz = nu (sigma_xx + sigma_yy), which holds for
    // the B-bar stress too (its in-plane trace is 2 K theta_bar and
    // sigma_zz = lambda theta_bar = 2 nu K theta_bar).
    return dim == 2 && !plane_stress ? poissons_ratio * trace(stress) : 0.;
  }



  template <int dim>
  double
  LinearElasticMaterial<dim>::mean_stress(const double volumetric_strain) const
  {
    const double in_plane_trace = dim * bulk_modulus * volumetric_strain;
    const double out_of_plane =
      dim == 2 && !plane_stress ? poissons_ratio * in_plane_trace : 0.;
    return (in_plane_trace + out_of_plane) / 3.;
  }



  template <int dim>
  std::string
  LinearElasticMaterial<dim>::describe() const
  {
    std::string text = "E = " + Input::to_text(youngs_modulus) +
                       ", nu = " + Input::to_text(poissons_ratio);
    if (dim == 2)
      text += plane_stress ? ", plane stress" : ", plane strain";
    if (mean_dilatation)
      text += ", B-bar element";
    return text;
  }



  template <int dim>
  std::string
  LinearElasticMaterial<dim>::locking_warning() const
  {
    if (!standard_forced || plane_stress ||
        !(poissons_ratio > locking_threshold))
      return "";
    return "Warning: the standard Q1 element locks at nu = " +
           Input::to_text(poissons_ratio) +
           " (too stiff, wrong contact pressures); set <Material/Formulation> "
           "= B-bar (or auto, which picks it above nu = 0.45)";
  }

  template class LinearElasticMaterial<2>;
  template class LinearElasticMaterial<3>;
} // namespace FrictionalContact
