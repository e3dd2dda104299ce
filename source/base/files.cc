#include <deal.II/base/mpi.h>

#include <frictional_contact/base/files.h>
#include <frictional_contact/base/input.h>

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace FrictionalContact
{
  void
  throw_write_failure(const std::string &file_name, const int error_number)
  {
    const std::string message =
      "cannot write '" + file_name + "': " + std::strerror(error_number);
    if (error_number == ENOSPC || error_number == EDQUOT ||
        error_number == EFBIG || error_number == EIO)
      throw WriteError(message);
    throw InputError(message + ": check <Output directory>");
  }



  void
  write_file_atomically(const std::string &file_name, const std::string &text)
  {
    const std::filesystem::path path(file_name);
    std::error_code             error;
    if (path.has_parent_path())
      {
        std::filesystem::create_directories(path.parent_path(), error);
        if (error)
          throw_write_failure(file_name, error.value());
      }
    // POSIX calls, not a stream: a full disk shows in write() or close(),
    // and errno says which.
    const std::string temporary  = file_name + ".tmp";
    const int         descriptor = ::open(temporary.c_str(),
                                  O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC,
                                  0644);
    if (descriptor < 0)
      throw_write_failure(file_name, errno);
    int         failure = 0;
    const char *data    = text.data();
    std::size_t left    = text.size();
    while (left > 0 && failure == 0)
      {
        const ssize_t written = ::write(descriptor, data, left);
        if (written < 0 && errno != EINTR)
          failure = errno;
        else if (written > 0)
          {
            data += written;
            left -= written;
          }
      }
    if (::close(descriptor) != 0 && failure == 0)
      failure = errno;
    if (failure == 0 && ::rename(temporary.c_str(), file_name.c_str()) != 0)
      failure = errno;
    if (failure != 0)
      {
        ::unlink(temporary.c_str());
        throw_write_failure(file_name, failure);
      }
  }



  std::string
  space_problem(const std::string &directory, const std::uintmax_t bytes)
  {
    const std::string placeholder =
      (directory.empty() ? std::string(".") : directory) + "/.space-reservation";
    const int descriptor =
      ::open(placeholder.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (descriptor < 0)
      return std::strerror(errno);
    // posix_fallocate returns the error number instead of setting errno.
    const int failure = ::posix_fallocate(descriptor, 0, std::max<std::uintmax_t>(bytes, 1));
    ::close(descriptor);
    ::unlink(placeholder.c_str());
    return failure == 0 ? std::string() : std::string(std::strerror(failure));
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



  namespace
  {
    /// What rank 0 tells the others of a failed write: its kind and message.
    enum class RootFailure : int
    {
      none,
      input,
      write
    };

    [[noreturn]] void
    rethrow_root_failure(const RootFailure kind, const std::string &message)
    {
      if (kind == RootFailure::write)
        throw WriteError(message);
      throw InputError(message);
    }
  } // namespace



  void
  run_on_root(const MPI_Comm comm, const std::function<void()> &work)
  {
    std::string problem;
    RootFailure kind = RootFailure::none;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          work();
        }
      catch (const WriteError &error)
        {
          kind    = RootFailure::write;
          problem = error.what();
        }
      catch (const InputError &error)
        {
          kind    = RootFailure::input;
          problem = error.what();
        }
      catch (const std::filesystem::filesystem_error &error)
        {
          try
            {
              throw_write_failure(error.path1().string(), error.code().value());
            }
          catch (const WriteError &write)
            {
              kind    = RootFailure::write;
              problem = write.what();
            }
          catch (const InputError &input)
            {
              kind    = RootFailure::input;
              problem = input.what();
            }
        }
      catch (const std::exception &error)
        {
          kind    = RootFailure::input;
          problem = "cannot write the output (" + Input::one_line(error.what()) +
                    "): check <Output directory> and the free disk space";
        }
    kind = static_cast<RootFailure>(
      dealii::Utilities::MPI::broadcast(comm, static_cast<int>(kind), 0));
    if (kind != RootFailure::none)
      rethrow_root_failure(kind, dealii::Utilities::MPI::broadcast(comm, problem, 0));
  }



  void
  run_collective_write(const MPI_Comm                comm,
                       const std::string            &file_name,
                       const std::function<void()>  &work)
  {
    std::string problem;
    try
      {
        work();
      }
    catch (const std::exception &error)
      {
        problem = Input::one_line(error.what(), 200);
      }
    if (!dealii::Utilities::MPI::logical_or(!problem.empty(), comm))
      return;
    // Name the cause as the system does: a write to the same folder says
    // whether space or quota ran out.
    std::string cause;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      {
        const std::filesystem::path folder =
          std::filesystem::path(file_name).parent_path();
        cause = space_problem(folder.string(), 1 << 20);
      }
    cause = dealii::Utilities::MPI::broadcast(comm, cause, 0);
    if (!cause.empty())
      throw WriteError("cannot write '" + file_name + "': " + cause);
    // Room enough: the cause is elsewhere (a file where a folder goes, a
    // folder without permission); the first rank's message says which.
    for (const std::string &message : dealii::Utilities::MPI::all_gather(comm, problem))
      if (!message.empty())
        throw InputError("cannot write '" + file_name + "' (" + message +
                         "): check <Output directory>");
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
