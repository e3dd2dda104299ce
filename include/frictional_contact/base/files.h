#pragma once

#include <mpi.h>

#include <cstdint>
#include <functional>
#include <string>

namespace FrictionalContact
{
  /**
   * Writes @p text to @p file_name through a temporary file and a rename,
   * so that a reader (or a run killed meanwhile) never sees a half-written
   * file. Creates the parent directory if needed. A failed write removes
   * the temporary and throws as throw_write_failure() says, naming the
   * file and the cause ("No space left on device", "Disk quota exceeded").
   */
  void
  write_file_atomically(const std::string &file_name, const std::string &text);

  /**
   * Throws for a failed write of @p file_name with the system's error
   * number @p error_number: a WriteError when space or quota ran out (or
   * the device failed), an InputError naming <Output directory> otherwise
   * (a file where a folder goes, no permission).
   */
  [[noreturn]] void
  throw_write_failure(const std::string &file_name, const int error_number);

  /**
   * Why files cannot grow in @p directory just now, found by reserving
   * @p bytes there (posix_fallocate of a placeholder, which also meets
   * quotas, unlike a query of the free space): the system's error message,
   * or "" if the reservation succeeded (it is released again).
   */
  std::string
  space_problem(const std::string &directory, const std::uintmax_t bytes);

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
   * failure collective: every rank throws the same exception if it threw
   * anything (a WriteError stays one; anything else becomes an InputError),
   * so that no rank waits for one that has stopped. Synchronises the ranks
   * like a barrier.
   */
  void
  run_on_root(const MPI_Comm comm, const std::function<void()> &work);

  /**
   * Runs @p work (a collective write, such as a VTU file written with
   * MPI-IO) on every rank of @p comm, and makes a failure on any rank the
   * same exception on all of them, naming @p file_name: a WriteError if
   * reserving space in its folder fails (the cause then is that), else an
   * InputError with the failure's own message.
   */
  void
  run_collective_write(const MPI_Comm                 comm,
                       const std::string             &file_name,
                       const std::function<void()>   &work);
} // namespace FrictionalContact
