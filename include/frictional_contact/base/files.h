#pragma once

#include <mpi.h>

#include <functional>
#include <string>

namespace FrictionalContact
{
  /**
   * Writes @p text to @p file_name through a temporary file and a rename,
   * so that a reader (or a run killed meanwhile) never sees a half-written
   * file. Creates the parent directory if needed.
   */
  void
  write_file_atomically(const std::string &file_name, const std::string &text);

  /**
   * Checks, before the first solve, that files can be written in
   * @p directory: rank 0 creates it (with its parents) and writes and
   * removes a small file in it, then removes again the folders it created,
   * so that a run that fails later leaves the disk as it was. Every rank of
   * @p comm throws the same InputError, naming <Output directory>, if that
   * fails.
   */
  void
  check_output_directory(const std::string &directory, const MPI_Comm comm);

  /**
   * Runs @p work (writing files) on rank 0 of @p comm only, and makes its
   * failure collective: every rank throws the same InputError if it threw
   * anything, so that no rank waits for one that has stopped. Synchronises
   * the ranks like a barrier.
   */
  void
  run_on_root(const MPI_Comm comm, const std::function<void()> &work);
} // namespace FrictionalContact
