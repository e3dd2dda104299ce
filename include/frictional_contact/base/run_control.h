#pragma once

#include <mpi.h>

#include <stdexcept>
#include <string>

namespace FrictionalContact
{
  /**
   * What a batch scheduler or a user can do to a run from outside: send it
   * a signal, or start a second run into the same folder. Exit code 75
   * (EX_TEMPFAIL, "try again") goes with both: a run stopped by a signal
   * after writing its checkpoint, and a run that found its output folder
   * in use.
   */
  namespace RunControl
  {
    /// The exit code of a run stopped by a signal, or refused a busy folder.
    constexpr int exit_code_try_again = 75;

    /**
     * Handles SIGUSR1 and SIGUSR2 (mpirun forwards them; Slurm's --signal
     * sends one before the time limit) and SIGTERM and SIGINT (srun, kill,
     * Ctrl-C; mpirun turns its own SIGTERM and SIGINT into a SIGTERM to the
     * ranks, and a SIGKILL seconds later): the first one is recorded, for
     * stop_signal() to report; a second one stops the process at once.
     */
    void
    install_signal_handlers();

    /**
     * The signal any rank of @p comm has received (0 if none): the
     * decision of all ranks alike. Collective; every rank must call it at
     * the same point.
     */
    int
    stop_signal(const MPI_Comm comm);

    /// Whether @p signal asks to stop within seconds (SIGTERM, SIGINT)
    /// rather than after the current increment (SIGUSR1, SIGUSR2).
    bool
    urgent(const int signal);

    /// "SIGUSR1", ...
    std::string
    signal_name(const int signal);

    /**
     * Throws StopRequested if any rank of @p comm has received an urgent
     * signal. Collective: the contact solvers call it once per iteration.
     */
    void
    stop_if_urgent(const MPI_Comm comm);
  } // namespace RunControl

  /**
   * Thrown where a run stops on a signal: by a contact solver for an urgent
   * signal (the increment is dropped), or after an increment. The
   * Simulator writes the checkpoint of the last finished increment and
   * turns it into a StoppedBySignal with the line to print.
   */
  class StopRequested : public std::runtime_error
  {
  public:
    explicit StopRequested(const int signal)
      : std::runtime_error("stopped by " + RunControl::signal_name(signal))
      , signal(signal)
    {}

    const int signal;
  };

  /// The line of a run that stopped on a signal after its checkpoint;
  /// main() prints it and exits with RunControl::exit_code_try_again.
  class StoppedBySignal : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /// A run that found its output folder in use by another one; main()
  /// prints it and exits with RunControl::exit_code_try_again.
  class OutputFolderBusy : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * The lock that keeps a second run out of an output folder: a kernel
   * lock (flock) on '<Output directory>/.lock', held by rank 0 for the
   * run's lifetime. The kernel drops it when the process ends however it
   * ends, so a requeued job takes the folder of a run that died without a
   * manual step; the file names the holder (host, process, start) for the
   * message of a run that finds it taken. Removed again when the run ends,
   * with the folder if the run made it and wrote nothing else.
   */
  class OutputLock
  {
  public:
    /// Takes the lock of @p directory (made if needed); every rank throws
    /// the same OutputFolderBusy, naming the holder, if another run holds it.
    OutputLock(const std::string &directory, const MPI_Comm comm);

    ~OutputLock();

    OutputLock(const OutputLock &) = delete;
    OutputLock &
    operator=(const OutputLock &) = delete;

  private:
    std::string path;
    std::string directory;
    bool        made_directory = false;
    int         descriptor     = -1;
  };
} // namespace FrictionalContact
