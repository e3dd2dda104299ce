// The command-line program: reads a parameter file and runs the scene.
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <frictional_contact/fclib/fclib_problem.h>
#include <frictional_contact/fclib/fclib_solve.h>
#include <frictional_contact/base/input.h>
#include <frictional_contact/base/parameter_file.h>
#include <frictional_contact/base/run_control.h>
#include <frictional_contact/driver/simulator.h>

#include <algorithm>
#include <optional>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

using namespace FrictionalContact;

namespace
{
  const char *usage =
    "Usage: contact [options] <parameter file>\n"
    "Solves the quasi-static frictional contact problem of elastic bodies\n"
    "with each other (mortar pairs) and with rigid obstacles, described in a\n"
    "parameter file (see parameters/).\n"
    "Options:\n"
    "  --print-parameters [file]  print every parameter with its "
    "documentation\n"
    "                             and its value (the defaults, or as the "
    "file sets them)\n"
    "  --json                     with --print-parameters: as JSON, with "
    "defaults\n"
    "  --fclib-export <list>      write the incremental problems of these\n"
    "                             increments ('1,3' or 'all') as FCLIB files\n"
    "                             (sets Postprocess/FCLIB export/Increments)\n"
    "\n"
    "  contact --fclib <problem.hdf5> [options] [parameter file]\n"
    "solves an FCLIB global problem with the method of <Contact solver/Method>\n"
    "(semismooth Newton by default; settings from the parameter file's\n"
    "Contact solver and Linear solver subsections) and prints the residuals\n"
    "and FCLIB's error measure:\n"
    "  --solution <file.hdf5>     write the problem and its solution there\n"
    "  --evaluate <file.hdf5>     instead of solving, evaluate the solution\n"
    "                             stored in this file\n"
    "  --reference <file.hdf5>    with --evaluate: also print the relative\n"
    "                             difference to the solution stored here\n"
    "\n"
    "  --help                     this text\n"
    "  --version                  the program's version\n";

  /// The value of "Dimension" in the file (2 if it does not set it).
  unsigned int
  read_dimension(const ParameterFile &parameters)
  {
    ParameterHandler prm;
    prm.declare_entry("Dimension", "2", Patterns::Integer(2, 3), "");
    parameters.parse(prm, /*skip_undefined=*/true);
    return prm.get_integer("Dimension");
  }

  enum class Task
  {
    run,
    print_parameters,
    print_parameters_as_json
  };

  /// What the command line asks for.
  struct Options
  {
    std::string file_name;
    /// The parameter file, read once (empty without one).
    std::optional<ParameterFile> parameters;
    bool        print_parameters = false;
    bool        json             = false;
    std::string fclib_export;
    std::string fclib_problem;
    std::string solution;
    std::string evaluate;
    std::string reference;
  };

  template <int dim>
  void
  run(const Options &options, const Task task)
  {
    ParameterHandler prm;
    Simulator<dim>::declare_parameters(prm);
    if (options.parameters)
      options.parameters->parse(prm);
    if (!options.fclib_export.empty())
      {
        prm.enter_subsection("Postprocess");
        prm.enter_subsection("FCLIB export");
        prm.set("Increments", options.fclib_export);
        prm.leave_subsection();
        prm.leave_subsection();
      }
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

  /// The --fclib mode: solves or evaluates an FCLIB global problem.
  template <int dim>
  void
  run_fclib(const Options &options, FclibProblem problem)
  {
    ParameterHandler prm;
    Simulator<dim>::declare_parameters(prm);
    if (options.parameters)
      options.parameters->parse(prm);
    FclibSolve<dim> fclib(prm,
                          std::move(problem),
                          options.fclib_problem,
                          MPI_COMM_WORLD);
    if (!options.evaluate.empty())
      fclib.evaluate(options.evaluate, options.reference);
    else
      fclib.solve(options.solution);
  }



  /// Prints the one error line on the root rank. Standard output is flushed
  /// first and the line goes out in a single write, so that mpirun, which
  /// forwards the two streams separately, cannot split it.
  void
  report_error(const bool is_root, const std::string &message)
  {
    if (!is_root)
      return;
    std::cout.flush();
    std::cerr << ("Error: " + message + "\n") << std::flush;
  }
} // namespace



int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  RunControl::install_signal_handlers();
  const bool  is_root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  Options     options;
  try
    {
      for (int i = 1; i < argc; ++i)
        {
          const std::string argument = argv[i];
          // The value of an option such as --fclib <file>.
          const auto value = [&]() {
            if (i + 1 == argc)
              throw InputError("the option '" + argument +
                               "' needs a value; see contact --help");
            return std::string(argv[++i]);
          };
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
            options.print_parameters = true;
          else if (argument == "--json")
            options.json = true;
          else if (argument == "--fclib-export")
            options.fclib_export = value();
          else if (argument == "--fclib")
            options.fclib_problem = value();
          else if (argument == "--solution")
            options.solution = value();
          else if (argument == "--evaluate")
            options.evaluate = value();
          else if (argument == "--reference")
            options.reference = value();
          else if (!argument.empty() && argument[0] == '-')
            throw InputError("unknown option '" + argument +
                             "'; see contact --help");
          else if (options.file_name.empty())
            options.file_name = argument;
          else
            throw InputError("more than one parameter file given ('" +
                             options.file_name + "' and '" + argument +
                             "'); see contact --help");
        }
      const std::string &file_name = options.file_name;
      // A broken parameter file (or include) is reported before anything else.
      if (!file_name.empty())
        options.parameters.emplace(file_name);
      const bool fclib_mode = !options.fclib_problem.empty();
      if (!fclib_mode && (!options.solution.empty() ||
                          !options.evaluate.empty() ||
                          !options.reference.empty()))
        throw InputError("--solution, --evaluate and --reference go with "
                         "--fclib <problem.hdf5>; see contact --help");
      if (!options.reference.empty() && options.evaluate.empty())
        throw InputError("--reference goes with --evaluate; see contact --help");
      if (fclib_mode)
        {
          if (options.print_parameters || !options.fclib_export.empty())
            throw InputError("--fclib runs on its own, without "
                             "--print-parameters or --fclib-export; see "
                             "contact --help");
          FclibProblem problem = read_fclib_problem(options.fclib_problem);
          if (problem.spacedim == 2)
            run_fclib<2>(options, std::move(problem));
          else
            run_fclib<3>(options, std::move(problem));
          return 0;
        }
      if (file_name.empty() && !options.print_parameters)
        throw InputError("no parameter file given; see contact --help");

      const unsigned int dim = file_name.empty() ? 2 : read_dimension(*options.parameters);
      const Task task = !options.print_parameters ? Task::run :
                        options.json ? Task::print_parameters_as_json :
                                       Task::print_parameters;
      if (options.json && !options.print_parameters)
        throw InputError("--json goes with --print-parameters; see contact --help");
      if (dim == 2)
        run<2>(options, task);
      else
        run<3>(options, task);
    }
  catch (const InputError &e)
    {
      report_error(is_root, e.what());
      return 1;
    }
  catch (const WriteError &e)
    {
      report_error(is_root, e.what());
      return 74;
    }
  catch (const StoppedBySignal &e)
    {
      if (is_root)
        std::cerr << (std::string("Stopped: ") + e.what() + "\n") << std::flush;
      return RunControl::exit_code_try_again;
    }
  catch (const StopRequested &e)
    {
      report_error(is_root, std::string(e.what()) + "; nothing was written");
      return RunControl::exit_code_try_again;
    }
  catch (const OutputFolderBusy &e)
    {
      report_error(is_root, e.what());
      return RunControl::exit_code_try_again;
    }
  catch (const SolverError &e)
    {
      report_error(is_root, std::string("the solve failed: ") + e.what());
      return 2;
    }
  catch (const NonFiniteInput &e)
    {
      report_error(is_root, e.what());
      return 2;
    }
  catch (const ExceptionBase &e)
    {
      // Errors of deal.II's ParameterHandler name the file, line and entry.
      std::ostringstream info;
      e.print_info(info);
      report_error(is_root, Input::one_line(info.str()));
      return 1;
    }
  catch (const std::exception &e)
    {
      report_error(is_root, Input::one_line(e.what()));
      return 3;
    }
  return 0;
}
