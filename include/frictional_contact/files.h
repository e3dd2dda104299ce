#pragma once

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
} // namespace FrictionalContact
