#pragma once

#include <deal.II/base/parameter_handler.h>

#include <frictional_contact/contact_operator.h>
#include <frictional_contact/contact_problem.h>
#include <frictional_contact/fclib_problem.h>

#include <set>
#include <string>

namespace FrictionalContact
{
  /**
   * The FCLIB form of an incremental problem (doc/fclib.md): v = du,
   * M = K, f = p, H = [-t_n,j, T_t,j] per candidate (in the order of the
   * MPI ranks), w = (g_j, -obstacle slip). Collective; the result is
   * complete on rank 0 and empty elsewhere.
   */
  template <int dim>
  FclibProblem
  to_fclib(const IncrementalProblem<dim> &problem,
           const ContactOperator<dim>    &contact);

  /// The solution (du, r) in FCLIB's form for @p fclib (rank 0 only).
  template <int dim>
  FclibSolution
  to_fclib(const FclibProblem                  &fclib,
           const TrilinosWrappers::MPI::Vector &du,
           const std::vector<Tensor<1, dim>>   &r);

  /**
   * write_fclib() on rank 0 of @p comm; if it fails, every rank throws its
   * InputError. Collective.
   */
  void
  write_fclib(const MPI_Comm       comm,
              const std::string   &path,
              const FclibProblem  &problem,
              const FclibSolution *solution);

  /**
   * Writes the incremental problems of chosen increments to FCLIB files,
   * `<Output directory>/fclib-NNNNN.hdf5`, with the solution when the solve
   * converged. Owns the entry "Output/FCLIB export".
   */
  class FclibExport
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    FclibExport(ParameterHandler &prm, const std::string &output_directory);

    /// Throws an InputError if an increment named is past the last of a
    /// loading history of @p n_increments.
    void
    check_increments(const unsigned int n_increments) const;

    /// Whether increment @p increment (counted from 1) is to be written.
    bool
    wanted(const unsigned int increment) const
    {
      return all || increments.count(increment) > 0;
    }

    /// Writes increment @p increment; @p du and @p r are the solution if
    /// @p converged. Collective.
    template <int dim>
    void
    write(const unsigned int                   increment,
          const IncrementalProblem<dim>       &problem,
          const ContactOperator<dim>          &contact,
          const TrilinosWrappers::MPI::Vector &du,
          const std::vector<Tensor<1, dim>>   &r,
          const bool                           converged) const;

    /// The file of increment @p increment.
    std::string
    file_name(const unsigned int increment) const;

  private:
    std::string            directory;
    std::string            text;
    bool                   all = false;
    std::set<unsigned int> increments;
  };
} // namespace FrictionalContact
