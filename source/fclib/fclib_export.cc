#include <deal.II/base/mpi.h>

#include <frictional_contact/base/plugins.h>
#include <frictional_contact/base/files.h>
#include <frictional_contact/fclib/fclib_export.h>
#include <frictional_contact/base/input.h>

#include <iomanip>
#include <sstream>

namespace FrictionalContact
{
  namespace
  {
    /// The vector's entries on rank 0, in the order of the global indices.
    std::vector<double>
    gather(const TrilinosWrappers::MPI::Vector &vector)
    {
      const MPI_Comm comm = vector.get_mpi_communicator();
      std::vector<types::global_dof_index> indices;
      std::vector<double>                  values;
      for (const auto i : vector.locally_owned_elements())
        {
          indices.push_back(i);
          values.push_back(vector[i]);
        }
      const auto all_indices = Utilities::MPI::gather(comm, indices, 0);
      const auto all_values  = Utilities::MPI::gather(comm, values, 0);
      std::vector<double> result(
        Utilities::MPI::this_mpi_process(comm) == 0 ? vector.size() : 0);
      for (unsigned int rank = 0; rank < all_indices.size(); ++rank)
        for (unsigned int k = 0; k < all_indices[rank].size(); ++k)
          result[all_indices[rank][k]] = all_values[rank][k];
      return result;
    }

    /// Entries of all ranks on rank 0; the columns of rank q are shifted
    /// by @p column_offsets[q].
    std::vector<MatrixEntry>
    gather(const std::vector<types::global_dof_index> &rows,
           const std::vector<types::global_dof_index> &columns,
           const std::vector<double>                  &values,
           const std::vector<unsigned int>            &column_offsets,
           const MPI_Comm                              comm)
    {
      const auto all_rows    = Utilities::MPI::gather(comm, rows, 0);
      const auto all_columns = Utilities::MPI::gather(comm, columns, 0);
      const auto all_values  = Utilities::MPI::gather(comm, values, 0);
      std::vector<MatrixEntry> entries;
      for (unsigned int rank = 0; rank < all_rows.size(); ++rank)
        for (unsigned int k = 0; k < all_rows[rank].size(); ++k)
          entries.push_back(
            {static_cast<unsigned int>(all_rows[rank][k]),
             static_cast<unsigned int>(all_columns[rank][k] +
                                       column_offsets[rank]),
             all_values[rank][k]});
      return entries;
    }

    /// Per rank, the number of local contact columns before it.
    std::vector<unsigned int>
    column_offsets(const unsigned int n_local_columns, const MPI_Comm comm)
    {
      const auto counts = Utilities::MPI::all_gather(comm, n_local_columns);
      std::vector<unsigned int> offsets(counts.size(), 0);
      for (unsigned int rank = 1; rank < counts.size(); ++rank)
        offsets[rank] = offsets[rank - 1] + counts[rank - 1];
      return offsets;
    }
  } // namespace



  template <int dim>
  FclibProblem
  to_fclib(const IncrementalProblem<dim> &problem,
           const ContactOperator<dim>    &contact)
  {
    const TrilinosWrappers::SparseMatrix &K    = problem.stiffness.matrix("--fclib-export");
    const MPI_Comm                        comm = K.get_mpi_communicator();
    const auto offsets = column_offsets(dim * contact.n_local(), comm);
    const std::vector<unsigned int> no_offsets(offsets.size(), 0);

    std::vector<types::global_dof_index> rows, columns;
    std::vector<double>                  values;
    for (const auto row : K.locally_owned_range_indices())
      for (auto entry = K.begin(row); entry != K.end(row); ++entry)
        if (entry->value() != 0)
          {
            rows.push_back(row);
            columns.push_back(entry->column());
            values.push_back(entry->value());
          }

    FclibProblem fclib;
    fclib.spacedim = dim;
    fclib.n        = K.m();
    fclib.M        = gather(rows, columns, values, no_offsets, comm);

    // H: column k of candidate j is T_j e_k, with the normal negated
    // (FCLIB's r_n = -r_n >= 0 and u_n = gap).
    rows.clear();
    columns.clear();
    values.clear();
    std::vector<double> w, mu;
    for (unsigned int j = 0; j < contact.n_local(); ++j)
      {
        for (unsigned int k = 0; k < dim; ++k)
          {
            Tensor<1, dim> e;
            e[k]                   = 1;
            const Tensor<1, dim> x = contact.to_cartesian(j, e);
            for (unsigned int c = 0; c < dim; ++c)
              if (x[c] != 0)
                {
                  rows.push_back(contact.dof(j, c));
                  columns.push_back(dim * j + k);
                  values.push_back(k == 0 ? -x[c] : x[c]);
                }
          }
        w.push_back(problem.gaps[j]);
        for (unsigned int k = 1; k < dim; ++k)
          w.push_back(-problem.obstacle_slip[j][k]);
        mu.push_back(contact.friction_coefficient(j));
      }
    fclib.H = gather(rows, columns, values, offsets, comm);
    for (const auto &part : Utilities::MPI::gather(comm, w, 0))
      fclib.w.insert(fclib.w.end(), part.begin(), part.end());
    for (const auto &part : Utilities::MPI::gather(comm, mu, 0))
      fclib.mu.insert(fclib.mu.end(), part.begin(), part.end());
    fclib.f = gather(problem.load);
    return fclib;
  }



  template <int dim>
  FclibSolution
  to_fclib(const FclibProblem                  &fclib,
           const TrilinosWrappers::MPI::Vector &du,
           const std::vector<Tensor<1, dim>>   &r)
  {
    std::vector<double> local_r;
    for (const auto &r_j : r)
      for (unsigned int k = 0; k < dim; ++k)
        local_r.push_back(k == 0 ? -r_j[k] : r_j[k]);
    FclibSolution solution;
    solution.v = gather(du);
    for (const auto &part :
         Utilities::MPI::gather(du.get_mpi_communicator(), local_r, 0))
      solution.r.insert(solution.r.end(), part.begin(), part.end());
    if (Utilities::MPI::this_mpi_process(du.get_mpi_communicator()) == 0)
      solution.u = local_velocity(fclib, solution.v);
    return solution;
  }



  void
  write_fclib(const MPI_Comm       comm,
              const std::string   &path,
              const FclibProblem  &problem,
              const FclibSolution *solution)
  {
    run_on_root(comm, [&]() { write_fclib(path, problem, solution); });
  }



  template <int dim>
  void
  FclibExport<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Increments",
                      "",
                      Patterns::Anything(),
                      "Increments (counted from 1, comma-separated, or "
                      "'all') whose incremental problem is written to "
                      "fclib-NNNNN.hdf5 as an FCLIB global problem, with "
                      "the solution when the solve converged (see "
                      "doc/fclib.md). The command line's --fclib-export "
                      "sets it too.");
  }



  template <int dim>
  void
  FclibExport<dim>::parse_parameters(ParameterHandler  &prm,
                                     const std::string &output_directory,
                                     const MPI_Comm)
  {
    directory = output_directory;
    text      = prm.get("Increments");
    for (const std::string &item : Input::split(text, ','))
      if (item == "all")
        all = true;
      else
        {
          std::size_t end    = 0;
          long        number = 0;
          try
            {
              number = std::stol(item, &end);
            }
          catch (const std::exception &)
            {
              end = 0;
            }
          if (end != item.size() || number < 1)
            Input::fail("Postprocess/FCLIB export/Increments",
                        text,
                        "increment numbers from 1, separated by commas, or "
                        "'all'");
          increments.insert(number);
        }
  }



  template <int dim>
  void
  FclibExport<dim>::check_scene(const unsigned int n_increments,
                                const Model<dim>  &model) const
  {
    if (model.nonlinear() && writes_files())
      throw InputError(
        "<Postprocess/FCLIB export>: a body is nonlinear (" +
        model.get_materials().describe_nonlinearity() +
        "), and an FCLIB file holds a linear problem (M = K): export "
        "increments of linear elastic scenes, or remove fclib export from "
        "<Postprocess/List of postprocessors>");
    if (!increments.empty() && *increments.rbegin() > n_increments)
      Input::fail("Postprocess/FCLIB export/Increments",
                  text,
                  "increment " + std::to_string(*increments.rbegin()) +
                    " is past the last increment of the loading history (" +
                    std::to_string(n_increments) + ")");
  }



  template <int dim>
  std::string
  FclibExport<dim>::describe() const
  {
    if (!writes_files())
      return "";
    std::string which;
    for (const unsigned int increment : increments)
      which += (which.empty() ? "" : ", ") + std::to_string(increment);
    return "FCLIB problems of " +
           (all ? std::string("every increment") :
                  "increment" + std::string(increments.size() > 1 ? "s " : " ") +
                    which) +
           " (fclib-NNNNN.hdf5)";
  }



  template <int dim>
  std::string
  FclibExport<dim>::file_name(const unsigned int increment) const
  {
    std::ostringstream name;
    name << directory << "/fclib-" << std::setw(5) << std::setfill('0')
         << increment << ".hdf5";
    return name.str();
  }



  template <int dim>
  Postprocess::Columns
  FclibExport<dim>::execute(const Postprocess::IncrementResult<dim> &result)
  {
    write(result, true);
    return {};
  }



  template <int dim>
  void
  FclibExport<dim>::execute_failed(const Postprocess::IncrementResult<dim> &result)
  {
    write(result, false);
  }



  template <int dim>
  void
  FclibExport<dim>::write(const Postprocess::IncrementResult<dim> &result,
                          const bool converged) const
  {
    const IncrementOutcome<dim> &outcome = result.outcome;
    if (!(all || increments.count(result.increment) > 0) || !outcome.problem)
      return;
    FclibProblem fclib = to_fclib(*outcome.problem, result.model.get_contact());
    fclib.title = "frictional_contact increment " + std::to_string(result.increment);
    fclib.description =
      "Quasi-static incremental problem K du - p = T r of an elastic body "
      "(Q1 elements) against a rigid obstacle, mapped to FCLIB with v = du, "
      "M = K, f = p, H = [-t_n, T_t] per contact, w = (g, -obstacle slip); "
      "see doc/fclib.md of frictional_contact";
    FclibSolution solution;
    if (converged)
      solution = to_fclib(fclib, outcome.du_solved, outcome.reactions);
    write_fclib(result.model.get_mpi_communicator(),
                file_name(result.increment),
                fclib,
                converged ? &solution : nullptr);
  }



  template FclibProblem
  to_fclib(const IncrementalProblem<2> &, const ContactOperator<2> &);
  template FclibProblem
  to_fclib(const IncrementalProblem<3> &, const ContactOperator<3> &);
  template FclibSolution
  to_fclib(const FclibProblem &,
           const TrilinosWrappers::MPI::Vector &,
           const std::vector<Tensor<1, 2>> &);
  template FclibSolution
  to_fclib(const FclibProblem &,
           const TrilinosWrappers::MPI::Vector &,
           const std::vector<Tensor<1, 3>> &);

  FRICTIONAL_CONTACT_REGISTER_PLUGIN(
    Postprocess::Interface,
    FclibExport,
    "fclib export",
    "FCLIB files (fclib-NNNNN.hdf5) of the increments named in its entry "
    "Increments.")
} // namespace FrictionalContact
