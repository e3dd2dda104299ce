#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <frictional_contact/base/run_control.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <ctime>
#include <filesystem>

namespace FrictionalContact
{
  namespace RunControl
  {
    namespace
    {
      volatile std::sig_atomic_t received_signal = 0;

      extern "C" void
      record_signal(const int signal)
      {
        if (received_signal != 0)
          {
            // The second signal: stop at once, as if there were no handler.
            std::signal(signal, SIG_DFL);
            std::raise(signal);
            return;
          }
        received_signal = signal;
      }
    } // namespace



    void
    install_signal_handlers()
    {
      struct sigaction action = {};
      action.sa_handler       = record_signal;
      sigemptyset(&action.sa_mask);
      // Interrupted system calls resume: MPI and the file system go on.
      action.sa_flags = SA_RESTART;
      for (const int signal : {SIGUSR1, SIGUSR2, SIGTERM, SIGINT})
        sigaction(signal, &action, nullptr);
    }



    int
    stop_signal(const MPI_Comm comm)
    {
      // The largest number wins, so that all ranks agree on one signal;
      // SIGTERM (15) outranks SIGUSR1/2 (10, 12), and SIGINT (2) is only
      // taken when nothing else came.
      return dealii::Utilities::MPI::max(static_cast<int>(received_signal), comm);
    }



    bool
    urgent(const int signal)
    {
      return signal == SIGTERM || signal == SIGINT;
    }



    std::string
    signal_name(const int signal)
    {
      switch (signal)
        {
          case SIGUSR1:
            return "SIGUSR1";
          case SIGUSR2:
            return "SIGUSR2";
          case SIGTERM:
            return "SIGTERM";
          case SIGINT:
            return "SIGINT";
          default:
            return "signal " + std::to_string(signal);
        }
    }



    void
    stop_if_urgent(const MPI_Comm comm)
    {
      if (const int signal = stop_signal(comm); urgent(signal))
        throw StopRequested(signal);
    }
  } // namespace RunControl



  namespace
  {
    /// "host dardel-12, process 4711, since 2026-11-25 14:03:07 UTC".
    std::string
    holder_description()
    {
      char host[256] = "unknown";
      ::gethostname(host, sizeof(host) - 1);
      char              since[64];
      const std::time_t now = std::time(nullptr);
      std::strftime(since, sizeof(since), "%Y-%m-%d %H:%M:%S UTC", std::gmtime(&now));
      return std::string("host ") + host + ", process " +
             std::to_string(::getpid()) + ", since " + since;
    }
  } // namespace



  OutputLock::OutputLock(const std::string &output_directory, const MPI_Comm comm)
    : path((output_directory.empty() ? std::string(".") : output_directory) + "/.lock")
    , directory(output_directory.empty() ? std::string(".") : output_directory)
  {
    std::string holder;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::error_code error;
        made_directory = !std::filesystem::exists(directory, error);
        std::filesystem::create_directories(directory, error);
        descriptor = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
        if (descriptor >= 0 && ::flock(descriptor, LOCK_EX | LOCK_NB) != 0)
          {
            char        text[512] = {};
            const auto  n = ::pread(descriptor, text, sizeof(text) - 1, 0);
            holder = n > 0 ? std::string(text, n) : std::string("unknown");
            while (!holder.empty() && holder.back() == '\n')
              holder.pop_back();
            ::close(descriptor);
            descriptor = -1;
          }
        else if (descriptor >= 0)
          {
            const std::string me = holder_description() + "\n";
            if (::ftruncate(descriptor, 0) != 0 ||
                ::pwrite(descriptor, me.data(), me.size(), 0) < 0)
              {
                // The lock holds without the description; nothing to do.
              }
          }
        // A folder where no file can be made was refused before
        // (check_output_directory); without a file there is no lock.
      }
    holder = dealii::Utilities::MPI::broadcast(comm, holder, 0);
    if (!holder.empty())
      throw OutputFolderBusy("the output folder '" + directory +
                             "' is in use by another run (" + holder +
                             "): wait until it ends, or set <Output "
                             "directory> to another folder");
  }



  OutputLock::~OutputLock()
  {
    if (descriptor < 0)
      return;
    // Unlinked before the lock is released: a run that opens the path
    // afterwards makes a new file and locks that.
    ::unlink(path.c_str());
    ::close(descriptor);
    if (made_directory)
      {
        std::error_code error;
        if (std::filesystem::is_empty(directory, error))
          std::filesystem::remove(directory, error);
      }
  }
} // namespace FrictionalContact
