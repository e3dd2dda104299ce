#include <frictional_contact/base/input.h>
#include <frictional_contact/base/plugins.h>
#include <frictional_contact/material/material.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace FrictionalContact
{
  template <int dim>
  void
  ElasticConstants<dim>::declare_parameters(ParameterHandler &prm)
  {
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
                      "plane strain (a long body, the usual default), "
                      "plane stress (a thin plate, as in Kanno's example I) "
                      "or axisymmetric (a body of revolution: x is the "
                      "radius r >= 0, y the axis; the hoop strain u_r / r "
                      "and the weight 2 pi r of every integral are added, "
                      "forces are totals over the revolution, u_r = 0 on "
                      "the axis; every body of the scene or none). Ignored "
                      "in 3D, where axisymmetric is refused.");
    prm.declare_entry(
      "Formulation",
      "auto",
      Patterns::Anything(),
      "The element: 'standard' Q1, or 'B-bar', the mean-dilatation Q1 "
      "element (Hughes; the volumetric strain replaced by its cell average, "
      "which is Q1-P0 with the pressure condensed), which does not lock "
      "when the material is nearly incompressible. 'auto' uses B-bar when "
      "Poisson's ratio exceeds 0.45 (in 3D and plane strain; plane stress "
      "does not lock) or the law flows plastically (plastic flow keeps the "
      "volume, and the standard element locks where it flows), and the "
      "standard element otherwise. At finite strain B-bar is refused and "
      "'auto' gives J2 plasticity the cell's mean volume ratio for its "
      "pressure (the mean-dilatation element) and the elastic laws the "
      "standard element.");
    prm.declare_entry(
      "Kinematics",
      "small strain",
      Patterns::Anything(),
      "'small strain' (the strain is the symmetric displacement gradient, "
      "the equilibrium is written on the reference configuration) or "
      "'finite strain' (total Lagrangian: F = I + Grad u, the law gives "
      "the second Piola-Kirchhoff stress of the Green-Lagrange strain, the "
      "tangent has its geometric part; tractions and pressures stay dead "
      "loads per reference area). 'neo-Hookean' and 'nearly incompressible "
      "neo-Hookean' need finite strain; 'linear elastic' at finite strain "
      "is the St. Venant-Kirchhoff law; 'J2 plasticity' at finite strain "
      "is F = Fe Fp with the Hencky law and the exponential map (isotropic "
      "hardening only). The elastic laws take the standard element at "
      "finite strain (the nearly incompressible law averages the volume "
      "ratio over each cell itself).");
    prm.declare_entry(
      "Quadrature",
      "Gauss",
      Patterns::Anything(),
      "Where a finite-strain body's law is evaluated: 'Gauss', the 2 x 2 "
      "(x 2) Gauss points, or 'Gauss-Lobatto', the 3 x 3 (x 3) points that "
      "include each cell's corners (as exact for Q1, and 9/4 and 27/8 times "
      "the points). A Q1 cell can fold at a corner while det F stays "
      "positive at its Gauss points; with the corners among the points an "
      "energy that grows without bound as det F falls to zero at a point "
      "(the neo-Hookean law's; not St. Venant-Kirchhoff's) holds every "
      "corner open. For cells squeezed and sheared far, as at a held edge "
      "in front of an ironing die. Small strain takes 'Gauss'.");
  }



  namespace
  {
    std::string
    joined(const std::vector<std::string> &subsections)
    {
      std::string path;
      for (const std::string &name : subsections)
        path += (path.empty() ? "" : "/") + name;
      return path;
    }
  } // namespace



  BodyEntries::BodyEntries(const ParameterHandler         &prm,
                           const std::vector<std::string> &subsections,
                           const std::string              &body,
                           const std::vector<std::string> &all_bodies)
    : prm(prm)
    , subsections(subsections)
    , path(joined(subsections))
    , body_name(body)
    , all_bodies(all_bodies)
  {}



  std::string
  BodyEntries::get(const std::string &entry) const
  {
    const std::string text = prm.get(subsections, entry);
    if (text.find(':') == std::string::npos)
      return Input::trim(text);
    std::string value;
    bool        found = false;
    for (const std::string &item : Input::split(text, ';'))
      {
        const std::size_t colon = item.find(':');
        if (colon == std::string::npos)
          Input::fail(path_of(entry), text,
                      "one value for every body, or 'body: value' for each "
                      "body, separated by ';'");
        const std::string name = Input::trim(item.substr(0, colon));
        if (std::find(all_bodies.begin(), all_bodies.end(), name) == all_bodies.end())
          {
            std::string list;
            for (const std::string &known : all_bodies)
              list += (list.empty() ? "'" : ", '") + known + "'";
            Input::fail(path_of(entry), text,
                        "'" + name + "' is not a body of the geometry; its "
                        "bodies are " + list);
          }
        if (name == body_name)
          {
            value = Input::trim(item.substr(colon + 1));
            found = true;
          }
      }
    if (!found)
      Input::fail(path_of(entry), text, "a value for the body '" + body_name + "'");
    return value;
  }



  double
  BodyEntries::get_number(const std::string &entry) const
  {
    return Input::parse_number(path_of(entry), get(entry), "a number is expected");
  }



  template <int dim>
  ElasticConstants<dim>::ElasticConstants(const BodyEntries &entries,
                                          const bool         isochoric)
  {
    const std::string kinematics  = entries.get("Kinematics");
    if (kinematics != "small strain" && kinematics != "finite strain")
      Input::fail(entries.path_of("Kinematics"), kinematics,
                  "'small strain' or 'finite strain' is expected");
    finite_strain                 = kinematics == "finite strain";
    youngs_modulus                = entries.get_number("Young's modulus");
    poissons_ratio                = entries.get_number("Poisson's ratio");
    const std::string model       = entries.get("Two-dimensional model");
    const std::string formulation = entries.get("Formulation");
    if (model != "plane strain" && model != "plane stress" && model != "axisymmetric")
      Input::fail("Material/Two-dimensional model", model,
                  "'plane strain', 'plane stress' or 'axisymmetric' is expected");
    if (formulation != "auto" && formulation != "standard" && formulation != "B-bar")
      Input::fail("Material/Formulation", formulation,
                  "'auto', 'standard' or 'B-bar' is expected");
    plane_stress = dim == 2 && model == "plane stress";
    axisymmetric = model == "axisymmetric";
    if (finite_strain && plane_stress)
      Input::fail(entries.path_of("Kinematics"), kinematics,
                  "finite strain is written for plane strain and 3D: set "
                  "<Material/Two-dimensional model> = plane strain");
    if (finite_strain && formulation == "B-bar")
      Input::fail(entries.path_of("Formulation"), formulation,
                  "the B-bar element is a small-strain element: with "
                  "<Material/Kinematics> = finite strain take 'standard' "
                  "(or 'auto')");

    const std::string quadrature = entries.get("Quadrature");
    if (quadrature != "Gauss" && quadrature != "Gauss-Lobatto")
      Input::fail(entries.path_of("Quadrature"), quadrature,
                  "'Gauss' or 'Gauss-Lobatto' is expected");
    corner_points = quadrature == "Gauss-Lobatto";
    if (corner_points && !finite_strain)
      Input::fail(entries.path_of("Quadrature"), quadrature,
                  "the Gauss-Lobatto points hold a finite-strain cell's corners "
                  "open: set <Material/Kinematics> = finite strain for this "
                  "body, or take 'Gauss'");

    if (!(youngs_modulus > 0))
      Input::fail("Material/Young's modulus",
                  Input::to_text(youngs_modulus),
                  "a positive number is expected");
    if (!(poissons_ratio > -1 && poissons_ratio < 0.5))
      Input::fail("Material/Poisson's ratio",
                  Input::to_text(poissons_ratio),
                  "a number strictly between -1 and 0.5 is expected");

    const bool locks = !plane_stress && poissons_ratio > locking_threshold;
    mean_dilatation_for_flow =
      formulation == "auto" && !locks && isochoric && !plane_stress && !finite_strain;
    mean_dilatation = formulation == "B-bar" ||
                      (formulation == "auto" && !finite_strain &&
                       (locks || mean_dilatation_for_flow));
    mean_volume_ratio = finite_strain && isochoric && formulation == "auto";
    standard_forced   = formulation == "standard" || (finite_strain && !mean_volume_ratio);

    const double mu = youngs_modulus / (2. * (1. + poissons_ratio));
    double       lambda = youngs_modulus * poissons_ratio /
                    ((1. + poissons_ratio) * (1. - 2. * poissons_ratio));
    if (plane_stress)
      lambda = 2. * lambda * mu / (lambda + 2. * mu);
    shear_modulus   = mu;
    bulk_modulus    = lambda + 2. * mu / dim;
    bulk_modulus_3d = lambda + 2. * mu / 3.;

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
  ElasticConstants<dim>::stress(const SymmetricTensor<2, dim> &strain,
                                     const double volumetric_strain) const
  {
    return 2. * shear_modulus * deviator(strain) +
           bulk_modulus * volumetric_strain * unit_symmetric_tensor<dim>();
  }



  template <int dim>
  double
  ElasticConstants<dim>::out_of_plane_stress(
    const SymmetricTensor<2, dim> &stress) const
  {
    // Plane strain: sigma_zz = nu (sigma_xx + sigma_yy), which holds for
    // the B-bar stress too (its in-plane trace is 2 K theta_bar and
    // sigma_zz = lambda theta_bar = 2 nu K theta_bar).
    return dim == 2 && !plane_stress ? poissons_ratio * trace(stress) : 0.;
  }



  template <int dim>
  double
  ElasticConstants<dim>::mean_stress(const double volumetric_strain) const
  {
    const double in_plane_trace = dim * bulk_modulus * volumetric_strain;
    const double out_of_plane =
      dim == 2 && !plane_stress ? poissons_ratio * in_plane_trace : 0.;
    return (in_plane_trace + out_of_plane) / 3.;
  }



  template <int dim>
  std::string
  ElasticConstants<dim>::describe() const
  {
    std::string text = "E = " + Input::to_text(youngs_modulus) +
                       ", nu = " + Input::to_text(poissons_ratio);
    if (dim == 2)
      text += plane_stress ? ", plane stress" : axisymmetric ? ", axisymmetric" : ", plane strain";
    if (mean_dilatation)
      text += ", B-bar element";
    if (finite_strain)
      text += ", finite strain";
    if (corner_points)
      text += ", Gauss-Lobatto points";
    return text;
  }



  template <int dim>
  std::string
  ElasticConstants<dim>::locking_warning() const
  {
    if (!standard_forced || plane_stress ||
        !(poissons_ratio > locking_threshold))
      return "";
    if (finite_strain)
      return "Warning: the standard Q1 element locks at nu = " +
             Input::to_text(poissons_ratio) +
             " (too stiff, wrong contact pressures), and finite strain has "
             "no mean-dilatation element: keep nu <= 0.45 or take "
             "<Material/Kinematics> = small strain with the B-bar element";
    return "Warning: the standard Q1 element locks at nu = " +
           Input::to_text(poissons_ratio) +
           " (too stiff, wrong contact pressures); set <Material/Formulation> "
           "= B-bar (or auto, which picks it above nu = 0.45)";
  }

  template <int dim>
  void
  MaterialModel<dim>::parse_parameters(const BodyEntries &material,
                                       const BodyEntries & /*own*/)
  {
    elastic_constants =
      std::make_unique<ElasticConstants<dim>>(material, flows_isochorically());
  }



  template <int dim>
  std::string
  MaterialModel<dim>::describe() const
  {
    return elastic_constants->describe();
  }



  template <int dim>
  void
  Materials<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    std::string names, documentation;
    for (const std::string &name : PluginRegistry<MaterialModel<dim>>::names())
      names += (names.empty() ? "'" : "', '") + name;
    prm.declare_entry("Model",
                      "linear elastic",
                      Patterns::Anything(),
                      "The material law of each body, one for all bodies or "
                      "'base: linear elastic; block: J2 plasticity': " + names +
                        "'. Each law reads the elastic entries of this "
                        "subsection and its own subsection.");
    ElasticConstants<dim>::declare_parameters(prm);
    PluginRegistry<MaterialModel<dim>>::declare_subsections(prm);
    prm.leave_subsection();
  }



  template <int dim>
  Materials<dim>::Materials(ParameterHandler                                &prm,
                            const std::map<std::string, types::material_id> &bodies)
  {
    std::vector<std::string> all_bodies;
    for (const auto &[name, id] : bodies)
      all_bodies.push_back(name);
    const std::vector<std::string> laws = PluginRegistry<MaterialModel<dim>>::names();
    for (const auto &[name, id] : bodies)
      {
        const BodyEntries material(prm, {"Material"}, name, all_bodies);
        const std::string law = material.get("Model");
        if (std::find(laws.begin(), laws.end(), law) == laws.end())
          {
            std::string list;
            for (const std::string &known : laws)
              list += (list.empty() ? "'" : ", '") + known + "'";
            Input::fail("Material/Model", prm.get({"Material"}, "Model"),
                        "one of " + list + " (for every body, or per body)");
          }
        materials[id] = PluginRegistry<MaterialModel<dim>>::create_unparsed(law);
        const BodyEntries own(
          prm,
          {"Material", PluginRegistry<MaterialModel<dim>>::subsection_name(law)},
          name,
          all_bodies);
        materials[id]->parse_parameters(material, own);
        names[id]     = name;
        law_names[id] = law;
        const bool finite_strain = materials[id]->elastic().finite_strain;
        if (finite_strain && !materials[id]->allows_finite_strain())
          Input::fail(material.path_of("Kinematics"), "finite strain",
                      "the law '" + law + "' of the body '" + name +
                        "' is written for small strain only: take "
                        "'neo-Hookean', 'nearly incompressible neo-Hookean' or "
                        "'linear elastic' at finite strain");
        if (materials[id]->elastic().corner_points &&
            materials[id]->n_history_values() > 0)
          Input::fail(material.path_of("Quadrature"), "Gauss-Lobatto",
                      "the law '" + law + "' of the body '" + name +
                        "' keeps a history, which lives at the Gauss points: "
                        "take 'Gauss'");
        if (!finite_strain && materials[id]->needs_finite_strain())
          Input::fail(material.path_of("Kinematics"), "small strain",
                      "the law '" + law + "' of the body '" + name +
                        "' is a finite-strain law: set <Material/Kinematics> "
                        "= finite strain");
        if constexpr (dim == 2)
          if (materials[id]->elastic().axisymmetric)
            {
              // The 3D law of the same entries: its strain has the hoop
              // component.
              revolved_laws[id] = PluginRegistry<MaterialModel<3>>::create_unparsed(law);
              revolved_laws[id]->parse_parameters(material, own);
            }
      }
    const std::string model = prm.get({"Material"}, "Two-dimensional model");
    for (const auto &[id, law] : materials)
      if (dim == 3 && law->elastic().axisymmetric)
        Input::fail("Material/Two-dimensional model", model,
                    "an axisymmetric scene is a 2D section of a body of "
                    "revolution: set Dimension = 2, or take 'plane strain' "
                    "(ignored in 3D)");
    if (!revolved_laws.empty() && revolved_laws.size() != materials.size())
      Input::fail("Material/Two-dimensional model", model,
                  "'axisymmetric' for every body of the scene or for none "
                  "(the axis and the weight 2 pi r belong to the whole scene)");
  }



  template <int dim>
  const MaterialModel<3> &
  Materials<dim>::revolved(const types::material_id id) const
  {
    const auto it = revolved_laws.find(id);
    Assert(it != revolved_laws.end(), ExcMessage("not an axisymmetric body"));
    return *it->second;
  }



  template <int dim>
  const MaterialModel<dim> &
  Materials<dim>::of(const types::material_id id) const
  {
    const auto it = materials.find(id);
    Assert(it != materials.end(), ExcMessage("a cell of no body"));
    return *it->second;
  }



  template <int dim>
  bool
  Materials<dim>::all_linear() const
  {
    for (const auto &[id, material] : materials)
      if (!material->is_linear() || material->elastic().finite_strain)
        return false;
    return true;
  }



  template <int dim>
  std::string
  Materials<dim>::describe_nonlinearity() const
  {
    std::vector<std::string> causes;
    const auto add = [&causes](const std::string &cause) {
      if (std::find(causes.begin(), causes.end(), cause) == causes.end())
        causes.push_back(cause);
    };
    for (const auto &[id, material] : materials)
      {
        if (!material->is_linear())
          add("<Material/Model> = " + law_names.at(id));
        if (material->elastic().finite_strain)
          add("<Material/Kinematics> = finite strain");
      }
    std::string text;
    for (const std::string &cause : causes)
      text += (text.empty() ? "" : ", ") + cause;
    return text;
  }



  template <int dim>
  bool
  Materials<dim>::any_finite_strain() const
  {
    for (const auto &[id, material] : materials)
      if (material->elastic().finite_strain)
        return true;
    return false;
  }



  template <int dim>
  double
  Materials<dim>::largest_modulus_ratio() const
  {
    double smallest = std::numeric_limits<double>::max(), largest = 0;
    for (const auto &[id, material] : materials)
      {
        smallest = std::min(smallest, material->elastic().youngs_modulus);
        largest  = std::max(largest, material->elastic().youngs_modulus);
      }
    return materials.empty() ? 1. : largest / smallest;
  }



  template <int dim>
  unsigned int
  Materials<dim>::max_history_values() const
  {
    unsigned int n = 0;
    for (const auto &[id, material] : materials)
      n = std::max(n, history_size(id));
    return n;
  }



  template <int dim>
  bool
  Materials<dim>::any_mean_dilatation() const
  {
    for (const auto &[id, material] : materials)
      if (material->elastic().mean_dilatation)
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
      if (const std::string warning = material->elastic().locking_warning();
          !warning.empty())
        warnings.push_back(materials.size() == 1 ?
                             warning :
                             warning + " (body '" + names.at(id) + "')");
    return warnings;
  }

  template class ElasticConstants<2>;
  template class ElasticConstants<3>;
  template class MaterialModel<2>;
  template class MaterialModel<3>;
  template class Materials<2>;
  template class Materials<3>;
} // namespace FrictionalContact
