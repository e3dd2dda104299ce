#include <frictional_contact/files.h>
#include <frictional_contact/input.h>

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
} // namespace FrictionalContact
