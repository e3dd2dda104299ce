#include <deal.II/base/mpi.h>
#include <deal.II/distributed/solution_transfer.h>

#include <frictional_contact/checkpoint.h>
#include <frictional_contact/files.h>
#include <frictional_contact/input.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace FrictionalContact
{
  namespace
  {
    const char *mesh_file  = "/mesh";
    const char *state_file = "/state";
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
    // The state file is written last: if it is there, all is.
    return std::filesystem::exists(directory + state_file);
  }



  template <int dim>
  void
  Checkpoint<dim>::save(
    const parallel::distributed::Triangulation<dim> &triangulation,
    const DoFHandler<dim>                           &dof_handler,
    const std::vector<const Vector *>               &vectors,
    const std::string                               &state) const
  {
    const bool        root      = Utilities::MPI::this_mpi_process(comm) == 0;
    const std::string temporary = directory + ".new";
    if (root)
      {
        std::filesystem::remove_all(temporary);
        std::filesystem::create_directories(temporary);
      }
    MPI_Barrier(comm);

    parallel::distributed::SolutionTransfer<dim, Vector> transfer(dof_handler);
    transfer.prepare_for_serialization(vectors);
    triangulation.save(temporary + mesh_file);
    if (root)
      write_file_atomically(temporary + state_file, state);
    MPI_Barrier(comm);

    if (root)
      {
        const std::string old = directory + ".old";
        std::filesystem::remove_all(old);
        if (std::filesystem::exists(directory))
          std::filesystem::rename(directory, old);
        std::filesystem::rename(temporary, directory);
        std::filesystem::remove_all(old);
      }
    MPI_Barrier(comm);
  }



  template <int dim>
  void
  Checkpoint<dim>::load_mesh(
    parallel::distributed::Triangulation<dim> &triangulation) const
  {
    if (!exists())
      throw InputError("<Resume computation> = true, but there is no "
                       "checkpoint in '" +
                       directory + "'; run without resuming first");
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
