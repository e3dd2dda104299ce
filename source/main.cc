// The command-line program: reads a parameter file and runs the scene.
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <frictional_contact/input.h>
#include <frictional_contact/simulator.h>

#include <fstream>
#include <iostream>
#include <sstream>

using namespace FrictionalContact;

namespace
{
  const char *usage =
    "Usage: contact [options] <parameter file>\n"
    "Solves the quasi-static frictional contact problem of an elastic body\n"
    "and rigid obstacles described in a parameter file (see parameters/).\n"
    "Options:\n"
    "  --print-parameters [file]  print every parameter with its "
    "documentation\n"
    "                             and its value (the defaults, or as the "
    "file sets them)\n"
    "  --json                     with --print-parameters: as JSON, with "
    "defaults\n"
    "  --help                     this text\n"
    "  --version                  the program's version\n";

  /// The file's text; an InputError if it cannot be read or has CR LF ends.
  std::string
  read_parameter_file(const std::string &file_name)
  {
    std::ifstream in(file_name);
    if (!in)
      throw InputError("cannot open the parameter file '" + file_name +
                       "': check the path");
    std::stringstream text;
    text << in.rdbuf();
    const std::string content = text.str();
    if (const auto cr = content.find('\r'); cr != std::string::npos)
      throw InputError(
        "the parameter file '" + file_name + "' has Windows line endings "
        "(CR LF, first on line " +
        std::to_string(1 + std::count(content.begin(), content.begin() + cr, '\n')) +
        "); convert it with: sed -i 's/\\r$//' " + file_name);
    return content;
  }

  /// The value of "Dimension" in the file (2 if it does not set it).
  unsigned int
  read_dimension(const std::string &file_name)
  {
    ParameterHandler prm;
    prm.declare_entry("Dimension", "2", Patterns::Integer(2, 3), "");
    prm.parse_input(file_name, "", /*skip_undefined=*/true);
    return prm.get_integer("Dimension");
  }

  enum class Task
  {
    run,
    print_parameters,
    print_parameters_as_json
  };

  template <int dim>
  void
  run(const std::string &file_name, const Task task)
  {
    ParameterHandler prm;
    Simulator<dim>::declare_parameters(prm);
    if (!file_name.empty())
      prm.parse_input(file_name);
    if (task != Task::run)
      {
        if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
          prm.print_parameters(std::cout,
                               task == Task::print_parameters ?
                                 ParameterHandler::PRM :
                                 ParameterHandler::JSON);
        return;
      }
    // Rethrow a failure only once the simulator (and its TimerOutput, which
    // would complain about an exception in flight) is gone.
    std::exception_ptr failure;
    {
      Simulator<dim> simulator(prm, MPI_COMM_WORLD);
      try
        {
          simulator.run();
        }
      catch (...)
        {
          failure = std::current_exception();
        }
    }
    if (failure)
      std::rethrow_exception(failure);
  }

  /// One line: the exception's own message without deal.II's frame.
  std::string
  one_line(const std::string &text)
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
          line += c;
          space = false;
        }
    return line;
  }
} // namespace



int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool  is_root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  std::string file_name;
  bool        print_parameters = false;
  bool        json             = false;
  try
    {
      for (int i = 1; i < argc; ++i)
        {
          const std::string argument = argv[i];
          if (argument == "--help" || argument == "-h")
            {
              if (is_root)
                std::cout << usage;
              return 0;
            }
          else if (argument == "--version")
            {
              if (is_root)
                std::cout << "contact " << FRICTIONAL_CONTACT_VERSION
                          << " (deal.II " << DEAL_II_PACKAGE_VERSION << ")\n";
              return 0;
            }
          else if (argument == "--print-parameters")
            print_parameters = true;
          else if (argument == "--json")
            json = true;
          else if (!argument.empty() && argument[0] == '-')
            throw InputError("unknown option '" + argument +
                             "'; see contact --help");
          else if (file_name.empty())
            file_name = argument;
          else
            throw InputError("more than one parameter file given ('" +
                             file_name + "' and '" + argument +
                             "'); see contact --help");
        }
      if (file_name.empty() && !print_parameters)
        throw InputError("no parameter file given; see contact --help");

      unsigned int dim = 2;
      if (!file_name.empty())
        {
          read_parameter_file(file_name);
          dim = read_dimension(file_name);
        }
      const Task task = !print_parameters ? Task::run :
                        json              ? Task::print_parameters_as_json :
                                            Task::print_parameters;
      if (json && !print_parameters)
        throw InputError("--json goes with --print-parameters; see contact --help");
      if (dim == 2)
        run<2>(file_name, task);
      else
        run<3>(file_name, task);
    }
  catch (const InputError &e)
    {
      if (is_root)
        std::cerr << "Error: " << e.what() << std::endl;
      return 1;
    }
  catch (const SolverError &e)
    {
      if (is_root)
        std::cerr << "Error: the solve failed: " << e.what() << std::endl;
      return 2;
    }
  catch (const ExceptionBase &e)
    {
      // Errors of deal.II's ParameterHandler name the file, line and entry.
      if (is_root)
        {
          std::ostringstream info;
          e.print_info(info);
          std::cerr << "Error: " << one_line(info.str()) << std::endl;
        }
      return 1;
    }
  catch (const std::exception &e)
    {
      if (is_root)
        std::cerr << "Error: " << one_line(e.what()) << std::endl;
      return 3;
    }
  return 0;
}
