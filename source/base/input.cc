#include <frictional_contact/base/input.h>

#include <iomanip>
#include <sstream>

namespace FrictionalContact
{
  namespace Input
  {
    std::string
    trim(const std::string &text)
    {
      const auto begin = text.find_first_not_of(" \t\r\n");
      if (begin == std::string::npos)
        return "";
      const auto end = text.find_last_not_of(" \t\r\n");
      return text.substr(begin, end - begin + 1);
    }



    std::string
    to_text(const double value)
    {
      std::ostringstream stream;
      stream << (value == 0 ? 0. : value); // no "-0"
      return stream.str();
    }



    std::string
    scientific(const double value, const unsigned int digits)
    {
      std::ostringstream stream;
      stream << std::scientific << std::setprecision(digits) << value;
      return stream.str();
    }



    std::vector<std::string>
    split(const std::string &text, const char separator)
    {
      std::vector<std::string> pieces;
      std::string              piece;
      std::istringstream       stream(text);
      while (std::getline(stream, piece, separator))
        if (const std::string trimmed = trim(piece); !trimmed.empty())
          pieces.push_back(trimmed);
      return pieces;
    }



    std::string
    one_line(const std::string &text, const std::size_t max_length)
    {
      std::string line;
      bool        space = false;
      for (const char c : text)
        if (std::isspace(static_cast<unsigned char>(c)))
          space = !line.empty();
        else
          {
            if (space)
              line += ' ';
            line += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
            space = false;
          }
      if (line.size() > max_length)
        line = line.substr(0, max_length - 3) + "...";
      return line;
    }



    void
    require_finite(const double value, const std::string &entry, const double t)
    {
      if (!std::isfinite(value))
        throw NonFiniteInput("<" + entry + "> is " +
                             (std::isnan(value) ? "NaN" : value > 0 ? "+inf" : "-inf") +
                             " at t = " +
                             to_text(t) +
                             "; change it so that it is finite at every time "
                             "of the loading history");
    }



    void
    fail(const std::string &entry,
         const std::string &value,
         const std::string &allowed)
    {
      throw InputError("<" + entry + "> = '" + value + "' is not valid: " +
                       allowed);
    }



    template <int dim>
    Tensor<1, dim>
    parse_vector(const std::string &entry, const std::string &text)
    {
      const std::vector<std::string> pieces = split(text, ',');
      const std::string allowed = std::to_string(dim) +
                                  " numbers separated by commas are expected "
                                  "(one per coordinate direction)";
      if (pieces.size() != dim)
        fail(entry, text, allowed);
      Tensor<1, dim> result;
      for (unsigned int d = 0; d < dim; ++d)
        {
          std::size_t end = 0;
          try
            {
              result[d] = std::stod(pieces[d], &end);
            }
          catch (const std::exception &)
            {
              fail(entry, text, allowed);
            }
          if (end != pieces[d].size() || !std::isfinite(result[d]))
            fail(entry, text, allowed);
        }
      return result;
    }



    double
    parse_number(const std::string &entry,
                 const std::string &text,
                 const std::string &allowed)
    {
      std::size_t end   = 0;
      double      value = 0;
      try
        {
          value = std::stod(text, &end);
        }
      catch (const std::exception &)
        {
          end = 0;
        }
      if (end == 0 || end != text.size() || !std::isfinite(value))
        fail(entry, text, allowed);
      return value;
    }



    template Tensor<1, 1>
    parse_vector<1>(const std::string &, const std::string &);
    template Tensor<1, 2>
    parse_vector<2>(const std::string &, const std::string &);
    template Tensor<1, 3>
    parse_vector<3>(const std::string &, const std::string &);
  } // namespace Input



  BoundaryNames::BoundaryNames(
    std::map<std::string, types::boundary_id> names,
    std::set<types::boundary_id>              ids_in_mesh)
    : names(std::move(names))
    , ids_in_mesh(std::move(ids_in_mesh))
  {}



  types::boundary_id
  BoundaryNames::id(const std::string &entry,
                    const std::string &name_or_number) const
  {
    types::boundary_id id = numbers::invalid_boundary_id;
    if (const auto it = names.find(name_or_number); it != names.end())
      id = it->second;
    else
      {
        std::size_t end = 0;
        try
          {
            const long value = std::stol(name_or_number, &end);
            if (end == name_or_number.size() && value >= 0 &&
                value < numbers::internal_face_boundary_id)
              id = static_cast<types::boundary_id>(value);
          }
        catch (const std::exception &)
          {}
      }
    if (id == numbers::invalid_boundary_id || ids_in_mesh.count(id) == 0)
      Input::fail(entry,
                  name_or_number,
                  "the mesh has the boundaries " + describe());
    return id;
  }



  std::string
  BoundaryNames::name(const types::boundary_id id) const
  {
    for (const auto &[name, named_id] : names)
      if (named_id == id)
        return name;
    return std::to_string(id);
  }



  std::string
  BoundaryNames::describe() const
  {
    std::string text;
    for (const types::boundary_id id : ids_in_mesh)
      {
        if (!text.empty())
          text += ", ";
        const std::string symbolic = name(id);
        text += symbolic == std::to_string(id) ?
                  symbolic :
                  symbolic + " (" + std::to_string(id) + ")";
      }
    return text;
  }
} // namespace FrictionalContact
