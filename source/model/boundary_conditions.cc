#include <frictional_contact/model/boundary_conditions.h>

namespace FrictionalContact
{
  template <int dim>
  void
  BoundaryConditions<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary conditions");
    prm.declare_entry(
      "Fixed boundaries",
      "",
      Patterns::Anything(),
      "Boundaries whose displacement is held at zero, separated by ';'. A "
      "boundary is a name of the geometry (such as left) or a boundary id. "
      "Append ': x', ': yz' etc. to hold only some components, as on a "
      "symmetry plane. Example: 'left; front: y'.");
    prm.declare_entry(
      "Prescribed boundaries",
      "",
      Patterns::Anything(),
      "Boundaries whose displacement follows <Prescribed displacement>, in "
      "the syntax of Fixed boundaries (e.g. 'top' or 'top: y'). A boundary "
      "both fixed and prescribed is fixed.");
    prm.declare_entry(
      "Prescribed displacement",
      dim == 2 ? "0; 0" : "0; 0; 0",
      Patterns::Anything(),
      "The displacement on the prescribed boundaries as a function of the "
      "position (x, y[, z]) and time t: one muParser expression per "
      "component, separated by ';'. Example: '0; -0.001 * min(t, 1)'.");
    prm.declare_entry(
      "Traction",
      "",
      Patterns::Anything(),
      "Surface tractions (force/area), separated by ';', each as "
      "'boundary: t_x, t_y[, t_z]'. Example: 'top: 0, -0.01'.");
    prm.declare_entry(
      "Pressure",
      "",
      Patterns::Anything(),
      "Pressures (force/area) normal to boundaries, pushing against the "
      "outward normal (a negative value pulls), separated by ';', each as "
      "'boundary: p'; they follow curved boundaries and scale with the load "
      "factor like the tractions. Example: 'inner: 0.01'.");
    prm.declare_entry("Body force",
                      dim == 2 ? "0, 0" : "0, 0, 0",
                      Patterns::Anything(),
                      "Force per volume acting on the whole body, as "
                      "'f_x, f_y[, f_z]' (e.g. '0, 0, -78500' for steel's "
                      "weight in SI units); scaled by the load factor like "
                      "the tractions.");
    prm.leave_subsection();
  }



  namespace
  {
    /// "left; front: y" -> boundary ids with component masks.
    template <int dim>
    std::vector<typename BoundaryConditions<dim>::FixedBoundary>
    parse_boundaries(const std::string   &entry,
                     const std::string   &text,
                     const BoundaryNames &names)
    {
      std::vector<typename BoundaryConditions<dim>::FixedBoundary> result;
      for (const std::string &item : Input::split(text, ';'))
        {
          const std::vector<std::string> parts = Input::split(item, ':');
          if (parts.empty() || parts.size() > 2)
            Input::fail(entry, item, "expected 'boundary' or 'boundary: xyz'");
          std::vector<bool> mask(dim, parts.size() == 1);
          if (parts.size() == 2)
            for (const char c : parts[1])
              {
                const int component = c - 'x';
                if (component < 0 || component >= dim)
                  Input::fail(entry,
                              item,
                              std::string("components are letters among ") +
                                (dim == 2 ? "x, y" : "x, y, z"));
                mask[component] = true;
              }
          result.push_back({names.id(entry, parts[0]), ComponentMask(mask)});
        }
      return result;
    }

    /// "top: 0, -1; right: 2, 0" in the entry @p entry -> (boundary id,
    /// n numbers) per item; the error shows @p example as the value part.
    template <int dim, int n>
    std::vector<std::pair<types::boundary_id, Tensor<1, n>>>
    boundary_values(const std::string   &entry,
                    const std::string   &example,
                    ParameterHandler    &prm,
                    const BoundaryNames &names)
    {
      const std::string path = "Boundary conditions/" + entry;
      std::vector<std::pair<types::boundary_id, Tensor<1, n>>> result;
      for (const std::string &item : Input::split(prm.get(entry), ';'))
        {
          const std::size_t colon = item.find(':');
          if (colon == std::string::npos)
            Input::fail(path, item, "expected 'boundary: " + example + "'");
          result.emplace_back(names.id(path, Input::trim(item.substr(0, colon))),
                              Input::parse_vector<n>(path, item.substr(colon + 1)));
        }
      return result;
    }
  } // namespace



  template <int dim>
  BoundaryConditions<dim>::BoundaryConditions(ParameterHandler    &prm,
                                              const BoundaryNames &names)
  {
    prm.enter_subsection("Boundary conditions");
    fixed_boundaries =
      parse_boundaries<dim>("Boundary conditions/Fixed boundaries",
                       prm.get("Fixed boundaries"),
                       names);
    prescribed_boundaries =
      parse_boundaries<dim>("Boundary conditions/Prescribed boundaries",
                       prm.get("Prescribed boundaries"),
                       names);
    for (const auto &prescribed : prescribed_boundaries)
      for (const auto &fixed : fixed_boundaries)
        if (fixed.id == prescribed.id)
          for (unsigned int c = 0; c < dim; ++c)
            if (fixed.components[c] && prescribed.components[c])
              {
                overridden.push_back(
                  "boundary '" + names.name(prescribed.id) +
                  "' is in both <Boundary conditions/Fixed boundaries> and "
                  "<Prescribed boundaries>; it is held fixed");
                c = dim;
              }
    const std::string expression = prm.get("Prescribed displacement");
    prescribed_displacement = std::make_unique<FunctionParser<dim>>(dim);
    try
      {
        prescribed_displacement->initialize(
          FunctionParser<dim>::default_variable_names() + ",t",
          expression,
          {{"pi", M_PI}},
          true);
        for (unsigned int c = 0; c < dim; ++c)
          prescribed_displacement->value(Point<dim>(), c);
      }
    catch (const ExceptionBase &)
      {
        Input::fail("Boundary conditions/Prescribed displacement",
                    expression,
                    "one muParser expression of x, y" +
                      std::string(dim == 3 ? ", z" : "") + " and t per "
                      "component, separated by ';'");
      }

    for (const auto &[id, traction] :
         boundary_values<dim, dim>("Traction", "t_x, t_y", prm, names))
      tractions[id] += traction;
    for (const auto &[id, pressure] :
         boundary_values<dim, 1>("Pressure", "p", prm, names))
      pressures[id] += pressure[0];

    body_force = Input::parse_vector<dim>("Boundary conditions/Body force",
                                          prm.get("Body force"));
    prm.leave_subsection();
  }

  template class BoundaryConditions<2>;
  template class BoundaryConditions<3>;
} // namespace FrictionalContact
