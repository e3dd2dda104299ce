#pragma once

#include <deal.II/base/parameter_handler.h>

#include <frictional_contact/base/input.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace FrictionalContact
{
  /**
   * The registry of one family of plugins (geometries, obstacles): for each
   * name a description, a function declaring the plugin's own parameters and
   * a factory. Plugins add themselves at program start with
   * FRICTIONAL_CONTACT_REGISTER_PLUGIN. The parameter file picks one by
   * `set Model name = <name>` (or another selector entry) in the family's
   * subsection; the plugin reads its parameters from a subsection named
   * like the plugin.
   */
  template <typename InterfaceType>
  class PluginRegistry
  {
  public:
    struct Plugin
    {
      std::string                                     description;
      std::function<void(ParameterHandler &)>         declare_parameters;
      std::function<std::unique_ptr<InterfaceType>()> create;
    };

    static bool
    add(const std::string &name, Plugin plugin)
    {
      plugins()[name] = std::move(plugin);
      return true;
    }

    /**
     * Declares @p selector (a selection among the registered names, its
     * documentation made of the plugins' descriptions) and one subsection per
     * plugin, inside the subsection the caller has entered.
     */
    static void
    declare_parameters(ParameterHandler  &prm,
                       const std::string &default_name,
                       const std::string &family_description,
                       const std::string &selector = "Model name")
    {
      std::string names, documentation = family_description + " Choices:";
      for (const auto &[name, plugin] : plugins())
        {
          names += (names.empty() ? "" : "|") + name;
          documentation += "\n'" + name + "': " + plugin.description;
        }
      prm.declare_entry(selector,
                        default_name,
                        Patterns::Selection(names),
                        documentation);
      for (const auto &[name, plugin] : plugins())
        {
          prm.enter_subsection(subsection_name(name));
          plugin.declare_parameters(prm);
          prm.leave_subsection();
        }
    }

    /// Creates the chosen plugin and lets it parse its subsection.
    static std::unique_ptr<InterfaceType>
    create(ParameterHandler &prm, const std::string &selector = "Model name")
    {
      const std::string name   = prm.get(selector);
      auto              plugin = plugins().at(name).create();
      prm.enter_subsection(subsection_name(name));
      plugin->parse_parameters(prm);
      prm.leave_subsection();
      return plugin;
    }

    /// The registered names, in alphabetical order.
    static std::vector<std::string>
    names()
    {
      std::vector<std::string> list;
      for (const auto &entry : plugins())
        list.push_back(entry.first);
      return list;
    }

    /// Declares the parameters of every plugin in a subsection named like
    /// it, inside the subsection the caller has entered (for families
    /// whose plugins are picked by a list, not by a selector entry).
    static void
    declare_subsections(ParameterHandler &prm)
    {
      for (const auto &[name, plugin] : plugins())
        {
          prm.enter_subsection(subsection_name(name));
          plugin.declare_parameters(prm);
          prm.leave_subsection();
        }
    }

    /// Creates the plugin @p name; the caller lets it parse its entries.
    static std::unique_ptr<InterfaceType>
    create_unparsed(const std::string &name)
    {
      return plugins().at(name).create();
    }

    /// "box" -> "Box", "from file" -> "From file", "fclib export" ->
    /// "FCLIB export".
    static std::string
    subsection_name(std::string name)
    {
      if (name.rfind("fclib", 0) == 0)
        name.replace(0, 5, "FCLIB");
      if (!name.empty())
        name[0] = static_cast<char>(std::toupper(name[0]));
      return name;
    }

  private:
    static std::map<std::string, Plugin> &
    plugins()
    {
      static std::map<std::string, Plugin> registry;
      return registry;
    }
  };
} // namespace FrictionalContact

/**
 * Registers the class template @p classname (instantiated for 2D and 3D) in
 * the registry of @p interface under @p name. Use once, in the plugin's .cc,
 * inside the plugin's namespace, with unqualified class names.
 */
#define FRICTIONAL_CONTACT_REGISTER_PLUGIN(interface, classname, name, description) \
  template class classname<2>;                                                       \
  template class classname<3>;                                                       \
  namespace                                                                          \
  {                                                                                  \
    template <int dim>                                                               \
    bool register_##classname()                                                      \
    {                                                                                \
      return ::FrictionalContact::PluginRegistry<interface<dim>>::add(               \
        name,                                                                        \
        {description,                                                                \
         &classname<dim>::declare_parameters,                                        \
         []() -> std::unique_ptr<interface<dim>> {                                   \
           return std::make_unique<classname<dim>>();                                \
         }});                                                                        \
    }                                                                                \
    const bool classname##_registered_2d = register_##classname<2>();                \
    const bool classname##_registered_3d = register_##classname<3>();                \
  }
