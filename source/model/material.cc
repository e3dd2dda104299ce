#include <frictional_contact/base/input.h>
#include <frictional_contact/model/material.h>

#include <algorithm>
#include <cmath>

namespace FrictionalContact
{
  template <int dim>
  void
  LinearElasticMaterial<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    prm.declare_entry("Young's modulus",
                      "1",
                      Patterns::Anything(),
                      "Young's modulus E (force/area, > 0). Like every "
                      "entry of this subsection, one value for all bodies, "
                      "or one per body of the geometry: 'base: 1000; "
                      "block: 1'.");
    prm.declare_entry("Poisson's ratio",
                      "0.3",
                      Patterns::Anything(),
                      "Poisson's ratio nu, in (-1, 0.5).");
    prm.declare_entry("Two-dimensional model",
                      "plane strain",
                      Patterns::Anything(),
                      "How a 2D computation models the third direction: "
                      "plane strain (a long body, the usual default) or "
                      "plane stress (a thin plate, as in Kanno's example I). "
                      "Ignored in 3D.");
    prm.declare_entry(
      "Formulation",
      "auto",
      Patterns::Anything(),
      "The element: 'standard' Q1, or 'B-bar', the mean-dilatation Q1 "
      "element (Hughes; the volumetric strain replaced by its cell average, "
      "which is Q1-P0 with the pressure condensed), which does not lock "
      "when the material is nearly incompressible. 'auto' uses B-bar when "
      "Poisson's ratio exceeds 0.45 (in 3D and plane strain; plane stress "
      "does not lock) and the standard element otherwise.");
    prm.leave_subsection();
  }



  namespace
  {
    /// The value of the entry @p entry of subsection Material for @p body:
    /// the whole text, or the part after 'body:' in 'a: 1; body: 2'. Each
    /// name must be one of @p bodies.
    std::string
    value_for(ParameterHandler               &prm,
              const std::string              &entry,
              const std::string              &body,
              const std::vector<std::string> &bodies)
    {
      const std::string text = prm.get(entry);
      if (text.find(':') == std::string::npos)
        return Input::trim(text);
      std::string value;
      bool        found = false;
      for (const std::string &item : Input::split(text, ';'))
        {
          const std::size_t colon = item.find(':');
          if (colon == std::string::npos)
            Input::fail("Material/" + entry, text,
                        "one value for every body, or 'body: value' for each "
                        "body, separated by ';'");
          const std::string name = Input::trim(item.substr(0, colon));
          if (std::find(bodies.begin(), bodies.end(), name) == bodies.end())
            {
              std::string list;
              for (const std::string &known : bodies)
                list += (list.empty() ? "'" : ", '") + known + "'";
              Input::fail("Material/" + entry, text,
                          "'" + name + "' is not a body of the geometry; its "
                          "bodies are " + list);
            }
          if (name == body)
            {
              value = Input::trim(item.substr(colon + 1));
              found = true;
            }
        }
      if (!found)
        Input::fail("Material/" + entry, text, "a value for the body '" + body + "'");
      return value;
    }
  } // namespace



  template <int dim>
  LinearElasticMaterial<dim>::LinearElasticMaterial(
    ParameterHandler               &prm,
    const std::string              &body,
    const std::vector<std::string> &all_bodies)
  {
    prm.enter_subsection("Material");
    const std::string young = value_for(prm, "Young's modulus", body, all_bodies);
    const std::string poisson = value_for(prm, "Poisson's ratio", body, all_bodies);
    const std::string model =
      value_for(prm, "Two-dimensional model", body, all_bodies);
    const std::string formulation = value_for(prm, "Formulation", body, all_bodies);
    prm.leave_subsection();
    youngs_modulus =
      Input::parse_number("Material/Young's modulus", young, "a number is expected");
    poissons_ratio =
      Input::parse_number("Material/Poisson's ratio", poisson, "a number is expected");
    if (model != "plane strain" && model != "plane stress")
      Input::fail("Material/Two-dimensional model", model,
                  "'plane strain' or 'plane stress' is expected");
    if (formulation != "auto" && formulation != "standard" && formulation != "B-bar")
      Input::fail("Material/Formulation", formulation,
                  "'auto', 'standard' or 'B-bar' is expected");
    plane_stress = dim == 2 && model == "plane stress";

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

  template <int dim>
  Materials<dim>::Materials(ParameterHandler                                &prm,
                            const std::map<std::string, types::material_id> &bodies)
  {
    std::vector<std::string> all_bodies;
    for (const auto &[name, id] : bodies)
      all_bodies.push_back(name);
    for (const auto &[name, id] : bodies)
      {
        materials[id] =
          std::make_unique<LinearElasticMaterial<dim>>(prm, name, all_bodies);
        names[id]     = name;
      }
  }



  template <int dim>
  const LinearElasticMaterial<dim> &
  Materials<dim>::of(const types::material_id id) const
  {
    const auto it = materials.find(id);
    Assert(it != materials.end(), ExcMessage("a cell of no body"));
    return *it->second;
  }



  template <int dim>
  bool
  Materials<dim>::any_mean_dilatation() const
  {
    for (const auto &[id, material] : materials)
      if (material->mean_dilatation)
        return true;
    return false;
  }



  template <int dim>
  std::string
  Materials<dim>::describe() const
  {
    if (materials.size() == 1)
      return materials.begin()->second->describe();
    std::string text;
    for (const auto &[id, material] : materials)
      text += (text.empty() ? "" : "; ") + names.at(id) + ": " + material->describe();
    return text;
  }



  template <int dim>
  std::vector<std::string>
  Materials<dim>::locking_warnings() const
  {
    std::vector<std::string> warnings;
    for (const auto &[id, material] : materials)
      if (const std::string warning = material->locking_warning(); !warning.empty())
        warnings.push_back(materials.size() == 1 ?
                             warning :
                             warning + " (body '" + names.at(id) + "')");
    return warnings;
  }

  template class LinearElasticMaterial<2>;
  template class LinearElasticMaterial<3>;
  template class Materials<2>;
  template class Materials<3>;
} // namespace FrictionalContact
