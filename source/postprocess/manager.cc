#include <deal.II/base/mpi.h>

#include <frictional_contact/base/files.h>
#include <frictional_contact/base/plugins.h>
#include <frictional_contact/postprocess/manager.h>

#include <boost/archive/text_iarchive.hpp>
#include <boost/archive/text_oarchive.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>

#include <algorithm>
#include <sstream>

namespace FrictionalContact
{
  namespace Postprocess
  {
    namespace
    {
      /// The postprocessors that place themselves in the default list, in
      /// their order.
      template <int dim>
      std::string
      default_postprocessors()
      {
        using Registry = PluginRegistry<Interface<dim>>;
        std::vector<std::pair<unsigned int, std::string>> placed;
        for (const std::string &name : Registry::names())
          if (const unsigned int position =
                Registry::create_unparsed(name)->default_position();
              position > 0)
            placed.emplace_back(position, name);
        std::sort(placed.begin(), placed.end());
        std::string list;
        for (const auto &entry : placed)
          list += (list.empty() ? "" : ", ") + entry.second;
        return list;
      }
    } // namespace



    template <int dim>
    void
    Manager<dim>::declare_parameters(ParameterHandler &prm)
    {
      using Registry = PluginRegistry<Interface<dim>>;
      std::string names;
      for (const std::string &name : Registry::names())
        names += (names.empty() ? "" : "|") + name;
      prm.enter_subsection("Postprocess");
      prm.declare_entry("List of postprocessors",
                        default_postprocessors<dim>(),
                        Patterns::MultipleSelection(names),
                        "What runs after each increment, in this order (the "
                        "order of their columns in the statistics file). "
                        "Each writes only what the entries of its "
                        "subsection ask for.");
      Registry::declare_subsections(prm);
      prm.leave_subsection();

      prm.enter_subsection("Output");
      prm.declare_entry("Write statistics",
                        "true",
                        Patterns::Bool(),
                        "Write the file 'statistics': one row per increment "
                        "(columns are described in its header).");
      prm.declare_entry("Checkpoint every",
                        "1",
                        Patterns::Integer(0),
                        "With more than one increment, save the state for "
                        "<Resume computation> after every n-th increment and "
                        "the last one (0: never).");
      prm.leave_subsection();
    }



    template <int dim>
    Manager<dim>::Manager(ParameterHandler  &prm,
                          const std::string &output_directory,
                          const MPI_Comm     comm)
      : statistics_file(output_directory + "/statistics")
      , comm(comm)
    {
      using Registry = PluginRegistry<Interface<dim>>;
      prm.enter_subsection("Output");
      write_statistics = prm.get_bool("Write statistics");
      checkpoint_every = prm.get_integer("Checkpoint every");
      prm.leave_subsection();
      prm.enter_subsection("Postprocess");
      for (const std::string &name :
           Input::split(prm.get("List of postprocessors"), ','))
        {
          postprocessors.push_back(Registry::create_unparsed(name));
          prm.enter_subsection(Registry::subsection_name(name));
          postprocessors.back()->parse_parameters(prm, output_directory, comm);
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }



    template <int dim>
    void
    Manager<dim>::check_scene(const unsigned int n_increments,
                              const Model<dim>  &model) const
    {
      for (const auto &postprocessor : postprocessors)
        postprocessor->check_scene(n_increments, model);
    }



    template <int dim>
    std::string
    Manager<dim>::describe(const unsigned int n_increments) const
    {
      std::string text;
      for (const auto &postprocessor : postprocessors)
        {
          const std::string part = postprocessor->describe();
          if (!part.empty())
            text += (text.empty() ? "" : ", ") + part;
        }
      if (write_statistics)
        text += (text.empty() ? "" : ", ") + std::string("statistics");
      if (checkpoint_due(n_increments, n_increments))
        text += (text.empty() ? "" : ", ") +
                std::string("checkpoint/ every ") +
                (checkpoint_every == 1 ? std::string("increment") :
                                         std::to_string(checkpoint_every) +
                                           " increments");
      if (writes_files())
        text += ", parameters.prm";
      return text;
    }



    template <int dim>
    bool
    Manager<dim>::writes_files() const
    {
      bool any = write_statistics;
      for (const auto &postprocessor : postprocessors)
        any = any || postprocessor->writes_files();
      return any;
    }



    template <int dim>
    bool
    Manager<dim>::needs_history() const
    {
      bool any = false;
      for (const auto &postprocessor : postprocessors)
        any = any || postprocessor->needs_history();
      return any;
    }



    template <int dim>
    bool
    Manager<dim>::checkpoint_due(const unsigned int increment,
                                 const unsigned int n_increments) const
    {
      return n_increments > 1 && checkpoint_every > 0 &&
             (increment % checkpoint_every == 0 || increment == n_increments);
    }



    template <int dim>
    void
    Manager<dim>::execute(const IncrementResult<dim> &result)
    {
      const Model<dim> &model = result.model;
      const auto       &contact = model.get_contact();
      Columns           columns = {
        {"Increment", std::uint64_t(result.increment)},
        {"Time", result.time},
        {"Load factor", result.load_factor},
        {"Free dofs d", std::uint64_t(model.get_body().n_free_dofs())},
        {"Contact candidates c",
         std::uint64_t(contact.active() ? contact.n_candidates() : 0)}};
      for (const auto &postprocessor : postprocessors)
        for (Column &column : postprocessor->execute(result))
          columns.push_back(std::move(column));

      statistics.add_row(columns);
      if (!write_statistics)
        return;
      // An axisymmetric run's forces and areas are those of the bodies of
      // revolution; the note has no colon, so that readers of the "# k:
      // label" lines pass it by.
      const std::string note =
        model.get_body().get_materials().axisymmetric() ?
          "# Axisymmetric section (x = r), every force and area a total "
          "over the full revolution (2 pi r included), every pressure per "
          "area\n" :
          "";
      run_on_root(comm, [&]() {
        write_file_atomically(statistics_file, note + statistics.text());
      });
    }



    template <int dim>
    void
    Manager<dim>::execute_failed(const IncrementResult<dim> &result)
    {
      for (const auto &postprocessor : postprocessors)
        postprocessor->execute_failed(result);
    }



    template <int dim>
    std::string
    Manager<dim>::save_state() const
    {
      std::vector<std::string> states;
      for (const auto &postprocessor : postprocessors)
        states.push_back(postprocessor->save_state());
      std::ostringstream            text;
      boost::archive::text_oarchive archive(text);
      statistics.save(archive);
      archive << states;
      return text.str();
    }



    template <int dim>
    void
    Manager<dim>::load_state(const std::string &state)
    {
      std::istringstream            text(state);
      boost::archive::text_iarchive archive(text);
      std::vector<std::string>      states;
      statistics.load(archive);
      archive >> states;
      if (states.size() != postprocessors.size())
        throw InputError("<Resume computation>: the checkpoint was written "
                         "with another <Postprocess/List of postprocessors>");
      for (unsigned int i = 0; i < states.size(); ++i)
        postprocessors[i]->load_state(states[i]);
    }

    template class Manager<2>;
    template class Manager<3>;
  } // namespace Postprocess
} // namespace FrictionalContact
