#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <utility>
#include <vector>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * A parameter file as the program reads it: its `include` lines expanded
   * and the relative paths in it resolved against the folder of the file
   * that has them (the included file's for its own lines), as users of
   * ASPECT expect, so that a scene runs from any working directory. The
   * paths are those of `include` and of `Mesh file`; <Output directory>
   * stays relative to the working directory. Owns the expanded text and
   * where each of its lines came from, so that deal.II's parse errors name
   * the real file and line.
   *
   * Every file read is checked: an InputError names the file and the fix
   * if it cannot be read, is a folder, is empty, is not text, starts with
   * a byte-order mark, has CR LF ends, or includes itself.
   */
  /// One `set` line of a parameter text: the entry's path ("Loading/End
  /// time"), its value, and the 0-based number of its line.
  struct ParameterEntry
  {
    std::string  path;
    std::string  value;
    unsigned int line;
  };

  /// The `set` lines of a parameter text (a file or deal.II's ShortPRM),
  /// with their subsections, comments removed.
  std::vector<ParameterEntry>
  parameter_entries(std::istream &text);

  class ParameterFile
  {
  public:
    explicit ParameterFile(const std::string &file_name);

    /// Parses the text into @p prm; a parse error becomes an InputError
    /// that names the file and line it came from.
    void
    parse(ParameterHandler &prm, const bool skip_undefined = false) const;

  private:
    /// Throws an InputError naming the new place of an entry that moved
    /// (such as Geometry/Global refinements), if the text sets one.
    void
    check_moved_entries() const;

    void
    expand(const std::string &file_name, std::vector<std::string> &including);

    std::string text;
    /// The file and 1-based line of each line of text.
    std::vector<std::pair<std::string, unsigned int>> origin;
  };
} // namespace FrictionalContact
