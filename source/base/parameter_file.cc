#include <frictional_contact/base/input.h>
#include <frictional_contact/base/parameter_file.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

namespace FrictionalContact
{
  namespace
  {
    /// The 1-based line of @p position in @p text.
    std::size_t
    line_of(const std::string &text, const std::size_t position)
    {
      return 1 + std::count(text.begin(), text.begin() + position, '\n');
    }



    /**
     * The position of the first byte that a text file does not have: a
     * control byte other than tab, line feed and a carriage return before
     * a line feed, or a byte outside a well-formed UTF-8 sequence; npos if
     * there is none.
     */
    std::size_t
    first_non_text_byte(const std::string &text)
    {
      for (std::size_t i = 0; i < text.size();)
        {
          const unsigned char c = text[i];
          if (c < 32 || c == 127)
            {
              const bool allowed =
                c == '\t' || c == '\n' ||
                (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n');
              if (!allowed)
                return i;
              ++i;
              continue;
            }
          // UTF-8: the lead byte gives the length, continuation bytes are
          // 10xxxxxx; overlong two-byte forms (C0, C1) and bytes above F4
          // never occur.
          const std::size_t length = c < 0x80 ? 1 :
                                     c >= 0xC2 && c <= 0xDF ? 2 :
                                     c >= 0xE0 && c <= 0xEF ? 3 :
                                     c >= 0xF0 && c <= 0xF4 ? 4 :
                                                              0;
          if (length == 0 || i + length > text.size())
            return i;
          for (std::size_t k = 1; k < length; ++k)
            if ((static_cast<unsigned char>(text[i + k]) & 0xC0) != 0x80)
              return i;
          i += length;
        }
      return std::string::npos;
    }



    /**
     * The file's text; an InputError, naming the file and the fix, if it
     * cannot be read, is a folder, is empty, is not text, starts with a
     * byte-order mark or has CR LF ends.
     */
    std::string
    checked_text(const std::string &file_name)
    {
      if (std::filesystem::is_directory(file_name))
        throw InputError("'" + file_name + "' is a folder, not a parameter file; "
                         "give a .prm file, e.g. parameters/example1.prm");
      std::ifstream in(file_name, std::ios::binary);
      if (!in)
        throw InputError("cannot open the parameter file '" + file_name +
                         "': check the path");
      std::stringstream text;
      text << in.rdbuf();
      const std::string content = text.str();
      if (content.find_first_not_of(" \t\r\n") == std::string::npos)
        throw InputError("the parameter file '" + file_name +
                         "' is empty; a scene sets at least its geometry, "
                         "supports and loads: start from parameters/example1.prm");
      if (content.rfind("\xEF\xBB\xBF", 0) == 0)
        throw InputError("the parameter file '" + file_name +
                         "' starts with a UTF-8 byte-order mark; save it "
                         "without one, e.g. with: sed -i '1s/^\\xEF\\xBB\\xBF//' " +
                         file_name);
      // Not text first (a binary file also has CR bytes), then CR LF.
      if (const std::size_t bad = first_non_text_byte(content);
          bad != std::string::npos)
        throw InputError("the parameter file '" + file_name +
                         "' is not a text file (" +
                         (static_cast<unsigned char>(content[bad]) < 32 ||
                              content[bad] == 127 ?
                            "a control byte" :
                            "a byte that is not UTF-8") +
                         " on line " + std::to_string(line_of(content, bad)) +
                         "); give a deal.II parameter file (.prm)");
      if (const auto cr = content.find('\r'); cr != std::string::npos)
        throw InputError(
          "the parameter file '" + file_name + "' has Windows line endings "
          "(CR LF, first on line " + std::to_string(line_of(content, cr)) +
          "); convert it with: sed -i 's/\\r$//' " + file_name);
      return content;
    }



    /// @p path against @p folder, unless it is absolute.
    std::string
    resolved(const std::string &path, const std::filesystem::path &folder)
    {
      const std::filesystem::path p(path);
      return p.is_absolute() ? path : (folder / p).lexically_normal().string();
    }
  } // namespace



  ParameterFile::ParameterFile(const std::string &file_name)
  {
    std::vector<std::string> including;
    expand(file_name, including);
  }



  void
  ParameterFile::expand(const std::string        &file_name,
                        std::vector<std::string> &including)
  {
    const std::string content = checked_text(file_name);
    const std::string identity =
      std::filesystem::weakly_canonical(file_name).string();
    if (std::find(including.begin(), including.end(), identity) != including.end())
      throw InputError("the parameter file '" + file_name +
                       "' includes itself (through 'include' lines); remove "
                       "the cycle");
    including.push_back(identity);

    const std::filesystem::path folder =
      std::filesystem::path(file_name).parent_path();
    static const std::regex include_line(R"(^\s*include\s+(\S.*?)\s*$)");
    // Mesh files (a geometry's, a rigid tool's) are named relative to the
    // parameter file that sets them.
    static const std::regex mesh_file_line(
      R"(^(\s*set\s+(?:Mesh file|Surface mesh)\s*=\s*)([^#\s][^#]*?)(\s*(#.*)?)$)");
    std::istringstream lines(content);
    std::string        line;
    for (unsigned int number = 1; std::getline(lines, line); ++number)
      {
        std::smatch match;
        if (std::regex_match(line, match, include_line))
          {
            expand(resolved(match[1], folder), including);
            continue;
          }
        if (std::regex_match(line, match, mesh_file_line))
          line = match[1].str() + resolved(match[2], folder) + match[3].str();
        text += line + '\n';
        origin.emplace_back(file_name, number);
      }
    including.pop_back();
  }



  namespace
  {
    /// Entries that moved, old path -> new path, so that a file written for
    /// an earlier release gets one line naming the new place instead of
    /// deal.II's "no entry with that name".
    const std::map<std::string, std::string> moved_entries = {
      {"Geometry/Global refinements", "Mesh refinement/Global refinements"},
      {"Geometry/Local refinements", "Mesh refinement/Local refinements"},
      {"Geometry/Refinement center", "Mesh refinement/Refinement center"},
      {"Geometry/Refinement radius", "Mesh refinement/Refinement radius"},
      {"Output/Postprocessors", "Postprocess/List of postprocessors"},
      {"Output/Write vtu", "Postprocess/Visualization/Write vtu"},
      {"Output/Write vtu every", "Postprocess/Visualization/Write vtu every"},
      {"Output/Write csv tables", "Postprocess/Visualization/Write csv tables"},
      {"Output/Number of grouped files",
       "Postprocess/Visualization/Number of grouped files"},
      {"Output/Write convergence history",
       "Postprocess/Convergence history/Write convergence history"},
      {"Output/FCLIB export", "Postprocess/FCLIB export/Increments"}};
  } // namespace



  std::vector<ParameterEntry>
  parameter_entries(std::istream &text)
  {
    std::vector<ParameterEntry> result;
    std::vector<std::string>    path;
    std::string                 line;
    for (unsigned int number = 0; std::getline(text, line); ++number)
      {
        line = Input::trim(line.substr(0, line.find('#')));
        if (line.rfind("subsection ", 0) == 0)
          path.push_back(Input::trim(line.substr(11)));
        else if (line == "end" && !path.empty())
          path.pop_back();
        else if (line.rfind("set ", 0) == 0 && line.find('=') != std::string::npos)
          {
            const auto  equals = line.find('=');
            std::string key;
            for (const auto &section : path)
              key += section + "/";
            key += Input::trim(line.substr(4, equals - 4));
            result.push_back(
              {key, Input::trim(line.substr(equals + 1)), number});
          }
      }
    return result;
  }



  void
  ParameterFile::check_moved_entries() const
  {
    std::istringstream lines(text);
    for (const ParameterEntry &entry : parameter_entries(lines))
      {
        const auto moved = moved_entries.find(entry.path);
        if (moved == moved_entries.end())
          continue;
        const std::string &now = moved->second;
        std::string        sections;
        for (const std::string &section :
             Input::split(now.substr(0, now.rfind('/')), '/'))
          sections +=
            (sections.empty() ? "'subsection " : ", 'subsection ") + section + "'";
        throw InputError("<" + entry.path + "> (line " +
                         std::to_string(origin[entry.line].second) + " of '" +
                         origin[entry.line].first + "') is now <" + now +
                         ">: set '" + now.substr(now.rfind('/') + 1) +
                         "' inside " + sections + " instead");
      }
  }



  void
  ParameterFile::parse(ParameterHandler &prm, const bool skip_undefined) const
  {
    check_moved_entries();
    std::istringstream in(text);
    try
      {
        prm.parse_input(in, "expanded", "", skip_undefined);
      }
    catch (const ExceptionBase &e)
      {
        // deal.II counts the lines of the expanded text: name the file and
        // the line they came from.
        std::ostringstream info;
        e.print_info(info);
        std::string       message = info.str();
        static const std::regex where(R"(Line <(\d+)> of file <expanded>)");
        std::smatch       match;
        if (std::regex_search(message, match, where))
          {
            const unsigned int line = std::stoul(match[1]);
            if (line >= 1 && line <= origin.size())
              message = match.prefix().str() + "Line <" +
                        std::to_string(origin[line - 1].second) + "> of file <" +
                        origin[line - 1].first + ">" + match.suffix().str();
          }
        throw InputError(Input::one_line(message));
      }
  }
} // namespace FrictionalContact
