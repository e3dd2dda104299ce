#include <deal.II/base/mpi.h>

#include <frictional_contact/base/files.h>
#include <frictional_contact/base/input.h>

#include <filesystem>
#include <fstream>

namespace FrictionalContact
{
  void
  write_file_atomically(const std::string &file_name, const std::string &text)
  {
    const std::filesystem::path path(file_name);
    if (path.has_parent_path())
      std::filesystem::create_directories(path.parent_path());
    const std::string temporary = file_name + ".tmp";
    {
      std::ofstream out(temporary);
      out << text;
      if (!out)
        throw InputError("cannot write '" + temporary +
                         "': check <Output directory> and the free disk space");
    }
    std::filesystem::rename(temporary, path);
  }



  namespace
  {
    /// Empty if a file can be written in @p directory, else why not.
    std::string
    why_not_writable(const std::filesystem::path &directory)
    {
      // The outermost folder that does not exist yet, to remove again.
      std::filesystem::path created;
      for (std::filesystem::path p = directory; !p.empty() && p != p.parent_path();
           p = p.parent_path())
        if (!std::filesystem::exists(p))
          created = p;
        else
          break;
      std::error_code error;
      std::filesystem::create_directories(directory, error);
      std::string problem;
      if (error)
        problem = "cannot create it (" + error.message() + ")";
      else
        {
          const std::filesystem::path probe = directory / ".write-test";
          {
            std::ofstream out(probe);
            out << "test\n";
            out.flush();
            if (!out)
              problem = "cannot write a file in it";
          }
          std::filesystem::remove(probe, error);
        }
      if (!created.empty())
        std::filesystem::remove_all(created, error);
      return problem;
    }
  } // namespace



  void
  run_on_root(const MPI_Comm comm, const std::function<void()> &work)
  {
    std::string problem;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          work();
        }
      catch (const InputError &error)
        {
          problem = error.what();
        }
      catch (const std::exception &error)
        {
          problem = "cannot write the output (" + Input::one_line(error.what()) +
                    "): check <Output directory> and the free disk space";
        }
    problem = dealii::Utilities::MPI::broadcast(comm, problem, 0);
    if (!problem.empty())
      throw InputError(problem);
  }



  void
  check_output_directory(const std::string &directory, const MPI_Comm comm)
  {
    std::string problem;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      problem = why_not_writable(directory.empty() ? "." : directory);
    problem = dealii::Utilities::MPI::broadcast(comm, problem, 0);
    if (!problem.empty())
      throw InputError("<Output directory> = '" + directory + "': " + problem +
                       "; choose a folder where you may write");
  }
} // namespace FrictionalContact
