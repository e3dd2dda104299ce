#include <deal.II/base/mpi.h>
#include <deal.II/distributed/solution_transfer.h>

#include <frictional_contact/driver/checkpoint.h>
#include <frictional_contact/base/files.h>
#include <frictional_contact/base/input.h>
#include <frictional_contact/base/parameter_file.h>

#include <boost/crc.hpp>

#include <cstdint>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace FrictionalContact
{
  namespace
  {
    const char *mesh_file     = "/mesh";
    const char *state_file    = "/state";
    const char *manifest_file = "/manifest";
    const char *format        = "contact checkpoint, format 2";

    /// "<size> <CRC-32 in hex>" of the file at @p path.
    std::string
    fingerprint(const std::filesystem::path &path)
    {
      std::ifstream     in(path, std::ios::binary);
      boost::crc_32_type crc;
      std::vector<char> buffer(1 << 16);
      std::uintmax_t    size = 0;
      while (in)
        {
          in.read(buffer.data(), buffer.size());
          crc.process_bytes(buffer.data(), in.gcount());
          size += in.gcount();
        }
      std::ostringstream text;
      text << size << ' ' << std::hex << crc.checksum();
      return text.str();
    }

    /// The entries of a ShortPRM text, by their path ("Loading/End time").
    std::map<std::string, std::string>
    entries(std::istream &prm)
    {
      std::map<std::string, std::string> result;
      for (const ParameterEntry &entry : parameter_entries(prm))
        result[entry.path] = entry.value;
      return result;
    }

    /// Whether the entry @p key can change the results (what is written
    /// where, and how often the screen hears of it, cannot).
    bool
    changes_result(const std::string &key)
    {
      return key != "Output directory" && key != "Resume computation" &&
             key.rfind("Output/", 0) != 0 &&
             key.rfind("Postprocess/", 0) != 0 &&
             key != "Contact solver/Report every";
    }

    /// Empty if the checkpoint in @p directory is intact and of @p scene
    /// (an entry it lacks matching at its value in @p defaults), else what
    /// is wrong with it and what to do.
    std::string
    check(const std::string &directory,
          const std::string &scene,
          const std::string &defaults)
    {
      const std::string start_afresh = "; delete that folder to start afresh";
      std::ifstream manifest(directory + manifest_file);
      if (!manifest)
        return "is not there; run without resuming first";
      std::string line;
      std::getline(manifest, line);
      if (line != format)
        return "was written in another format ('" + line.substr(0, 60) +
               "', this program reads '" + format + "')" + start_afresh;
      unsigned int n_files = 0;
      if (!(manifest >> line >> n_files) || line != "files")
        return "has a damaged manifest" + start_afresh;
      for (unsigned int i = 0; i < n_files; ++i)
        {
          std::string name, size, crc;
          if (!(manifest >> name >> size >> crc))
            return "has a damaged manifest" + start_afresh;
          const std::filesystem::path file = directory + "/" + name;
          if (!std::filesystem::exists(file))
            return "lacks its file '" + name + "'" + start_afresh;
          const std::string now = fingerprint(file);
          if (now != size + ' ' + crc)
            return "has a damaged file '" + name + "' (" +
                   now.substr(0, now.find(' ')) + " bytes, written with " + size +
                   (now.substr(0, now.find(' ')) == size ? ", another checksum)" : ")") +
                   start_afresh;
        }
      std::getline(manifest, line);
      std::getline(manifest, line);
      if (line != "scene")
        return "has a damaged manifest" + start_afresh;
      std::istringstream current(scene), by_default(defaults);
      const auto then = entries(manifest), now = entries(current),
                 default_values = entries(by_default);
      std::string  differences;
      unsigned int n_differences = 0;
      for (const auto &[key, value] : now)
        if (changes_result(key))
          {
            const auto old = then.find(key);
            const auto default_value = default_values.find(key);
            const bool at_default    = default_value != default_values.end() &&
                                    default_value->second == value;
            const std::string before = old != then.end() ? old->second :
                                       at_default        ? value :
                                                           "(not there)";
            if (before != value && ++n_differences <= 4)
              differences += std::string(differences.empty() ? "" : ", ") + "<" + key +
                             "> was '" + before + "', is '" + value + "'";
          }
      if (n_differences > 4)
        differences += " and " + std::to_string(n_differences - 4) + " more";
      if (!differences.empty())
        return "was written for another scene: " + differences +
               "; resume with the scene it was written for, or set Resume "
               "computation = false to start afresh";
      return "";
    }
  } // namespace



  template <int dim>
  Checkpoint<dim>::Checkpoint(const std::string &output_directory,
                              const MPI_Comm     comm)
    : directory(output_directory + "/checkpoint")
    , comm(comm)
  {}



  template <int dim>
  bool
  Checkpoint<dim>::exists() const
  {
    // Also one killed between the two renames of save(): complete in .new
    // (its manifest was written before), or still in .old.
    for (const std::string place : {"", ".new", ".old"})
      if (std::filesystem::exists(directory + place + manifest_file))
        return true;
    return false;
  }



  template <int dim>
  void
  Checkpoint<dim>::save(
    const parallel::distributed::Triangulation<dim> &triangulation,
    const DoFHandler<dim>                           &dof_handler,
    const std::vector<const Vector *>               &vectors,
    QuadratureHistory<dim>                          &history,
    const std::string                               &state,
    const std::string                               &scene) const
  {
    const std::string temporary = directory + ".new";
    // p4est aborts the program when its save fails: the space it needs is
    // reserved first, and a reservation that fails is a WriteError that
    // leaves the last checkpoint as it was.
    const std::uintmax_t bytes = expected_size(
      triangulation,
      dof_handler,
      vectors.size(),
      state.size() + scene.size() +
        Utilities::MPI::sum<std::uintmax_t>(history.size_in_bytes(), comm));
    run_on_root(comm, [&]() {
      std::filesystem::remove_all(temporary);
      std::filesystem::create_directories(temporary);
      if (const std::string problem = space_problem(temporary, bytes);
          !problem.empty())
        {
          std::error_code ignored;
          std::filesystem::remove_all(temporary, ignored);
          throw WriteError("cannot write the checkpoint in '" + temporary +
                           "': " + problem + " (reserving the " +
                           std::to_string(bytes / 1024 + 1) +
                           " kB it needs failed)");
        }
    });

    parallel::distributed::SolutionTransfer<dim, Vector> transfer(dof_handler);
    transfer.prepare_for_serialization(vectors);
    // Attached as deal.II's SolutionTransfer attaches its data: the mesh
    // saves what is attached to it and is otherwise unchanged.
    auto &mesh = const_cast<parallel::distributed::Triangulation<dim> &>(triangulation);
    history.attach(mesh);
    triangulation.save(temporary + mesh_file);
    history.clear_attachment();
    run_on_root(comm, [&]() { write_file_atomically(temporary + state_file, state); });

    run_on_root(comm, [&]() {
      // The manifest last, once every rank has written its part.
      std::vector<std::string> names;
      for (const auto &file : std::filesystem::directory_iterator(temporary))
        names.push_back(file.path().filename().string());
      std::sort(names.begin(), names.end());
      std::ostringstream manifest;
      manifest << format << "\nfiles " << names.size() << '\n';
      for (const auto &name : names)
        manifest << name << ' ' << fingerprint(temporary + "/" + name) << '\n';
      manifest << "scene\n" << scene;
      write_file_atomically(temporary + manifest_file, manifest.str());

      const std::string old = directory + ".old";
      std::filesystem::remove_all(old);
      if (std::filesystem::exists(directory))
        std::filesystem::rename(directory, old);
      std::filesystem::rename(temporary, directory);
      std::filesystem::remove_all(old);
    });
  }



  template <int dim>
  std::uintmax_t
  Checkpoint<dim>::expected_size(
    const parallel::distributed::Triangulation<dim> &triangulation,
    const DoFHandler<dim>                           &dof_handler,
    const unsigned int                               n_vectors,
    const std::uintmax_t                             text_bytes) const
  {
    // The last checkpoint's size, or what the mesh (p4est's quadrants, a
    // few dozen bytes each) and the vectors' values on each cell take,
    // whichever is larger, with a quarter and 64 kB to spare.
    std::uintmax_t last = 0;
    std::error_code error;
    for (const auto &file : std::filesystem::directory_iterator(directory, error))
      last += file.file_size(error);
    const std::uintmax_t cells = triangulation.n_global_active_cells();
    const std::uintmax_t per_cell =
      64 + sizeof(double) * dof_handler.get_fe().n_dofs_per_cell() * n_vectors;
    return 5 * std::max(last, cells * per_cell + text_bytes) / 4 + (1 << 16);
  }



  template <int dim>
  void
  Checkpoint<dim>::verify(const std::string &scene,
                          const std::string &defaults) const
  {
    std::string problem;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        // A save killed between its two renames left the checkpoint whole
        // in .new (manifest written) or in .old: put it back in place.
        std::error_code error;
        for (const std::string place : {".new", ".old"})
          if (!std::filesystem::exists(directory + manifest_file) &&
              std::filesystem::exists(directory + place + manifest_file))
            {
              std::filesystem::remove_all(directory, error);
              std::filesystem::rename(directory + place, directory, error);
            }
        problem = check(directory, scene, defaults);
      }
    problem = Utilities::MPI::broadcast(comm, problem, 0);
    if (!problem.empty())
      throw InputError("<Resume computation>: the checkpoint in '" + directory +
                       "' " + problem);
  }



  template <int dim>
  void
  Checkpoint<dim>::load_mesh(
    parallel::distributed::Triangulation<dim> &triangulation) const
  {
    triangulation.load(directory + mesh_file);
  }



  template <int dim>
  void
  Checkpoint<dim>::load_vectors(const DoFHandler<dim> &dof_handler,
                                std::vector<Vector *> &vectors) const
  {
    parallel::distributed::SolutionTransfer<dim, Vector> transfer(dof_handler);
    transfer.deserialize(vectors);
  }



  template <int dim>
  std::string
  Checkpoint<dim>::load_state() const
  {
    std::ifstream     in(directory + state_file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

  template class Checkpoint<2>;
  template class Checkpoint<3>;
} // namespace FrictionalContact
