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
    prm.leave_subsection();
  }



  template <int dim>
  LinearElasticMaterial<dim>::LinearElasticMaterial(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    youngs_modulus = prm.get_double("Young's modulus");
    poissons_ratio = prm.get_double("Poisson's ratio");
    plane_stress   = dim == 2 && prm.get("Two-dimensional model") == "plane stress";
    prm.leave_subsection();

    if (!(youngs_modulus > 0))
      Input::fail("Material/Young's modulus",
                  Input::to_text(youngs_modulus),
                  "a positive number is expected");
    if (!(poissons_ratio > -1 && poissons_ratio < 0.5))
      Input::fail("Material/Poisson's ratio",
                  Input::to_text(poissons_ratio),
                  "a number strictly between -1 and 0.5 is expected");

    const double mu = youngs_modulus / (2. * (1. + poissons_ratio));
    double       lambda = youngs_modulus * poissons_ratio /
                    ((1. + poissons_ratio) * (1. - 2. * poissons_ratio));
    if (plane_stress)
      lambda = 2. * lambda * mu / (lambda + 2. * mu);

    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int l = 0; l < dim; ++l)
            stiffness[i][j][k][l] =
              (i == j && k == l ? lambda : 0.) +
              (i == k && j == l ? mu : 0.) + (i == l && j == k ? mu : 0.);
  }



  template <int dim>
  std::string
  LinearElasticMaterial<dim>::describe() const
  {
    std::string text = "E = " + Input::to_text(youngs_modulus) +
                       ", nu = " + Input::to_text(poissons_ratio);
    if (dim == 2)
      text += plane_stress ? ", plane stress" : ", plane strain";
    return text;
  }

  template class LinearElasticMaterial<2>;
  template class LinearElasticMaterial<3>;
} // namespace FrictionalContact
