#include <frictional_contact/boundary_conditions.h>

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
      "Traction",
      "",
      Patterns::Anything(),
      "Surface tractions (force/area), separated by ';', each as "
      "'boundary: t_x, t_y[, t_z]'. Example: 'top: 0, -0.01'.");
    prm.declare_entry("Body force",
                      dim == 2 ? "0, 0" : "0, 0, 0",
                      Patterns::Anything(),
                      "Force per volume acting on the whole body.");
    prm.leave_subsection();
  }



  template <int dim>
  BoundaryConditions<dim>::BoundaryConditions(ParameterHandler    &prm,
                                              const BoundaryNames &names)
  {
    prm.enter_subsection("Boundary conditions");
    const std::string fixed_entry = "Boundary conditions/Fixed boundaries";
    for (const std::string &item : Input::split(prm.get("Fixed boundaries"), ';'))
      {
        const std::vector<std::string> parts = Input::split(item, ':');
        if (parts.empty() || parts.size() > 2)
          Input::fail(fixed_entry, item, "expected 'boundary' or 'boundary: xyz'");
        std::vector<bool> mask(dim, parts.size() == 1);
        if (parts.size() == 2)
          for (const char c : parts[1])
            {
              const int component = c - 'x';
              if (component < 0 || component >= dim)
                Input::fail(fixed_entry,
                            item,
                            std::string("components are letters among ") +
                              (dim == 2 ? "x, y" : "x, y, z"));
              mask[component] = true;
            }
        fixed_boundaries.push_back(
          {names.id(fixed_entry, parts[0]), ComponentMask(mask)});
      }

    const std::string traction_entry = "Boundary conditions/Traction";
    for (const std::string &item : Input::split(prm.get("Traction"), ';'))
      {
        const std::size_t colon = item.find(':');
        if (colon == std::string::npos)
          Input::fail(traction_entry, item, "expected 'boundary: t_x, t_y'");
        const types::boundary_id id =
          names.id(traction_entry, Input::trim(item.substr(0, colon)));
        tractions[id] += Input::parse_vector<dim>(traction_entry,
                                                  item.substr(colon + 1));
      }

    body_force = Input::parse_vector<dim>("Boundary conditions/Body force",
                                          prm.get("Body force"));
    prm.leave_subsection();
  }

  template class BoundaryConditions<2>;
  template class BoundaryConditions<3>;
} // namespace FrictionalContact
