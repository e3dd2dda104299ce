#pragma once

#include <deal.II/base/parameter_handler.h>

#include <frictional_contact/model/contact_operator.h>
#include <frictional_contact/solvers/contact_problem.h>
#include <frictional_contact/fclib/fclib_problem.h>
#include <frictional_contact/postprocess/interface.h>

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
   * converged (an increment that fails is written too, without it): the
   * postprocessor "fclib export", reading the entry "Increments" of its subsection "FCLIB export".
   */
  template <int dim>
  class FclibExport : public Postprocess::Interface<dim>
  {
  public:
    unsigned int
    default_position() const override
    {
      return 6;
    }

    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler  &prm,
                     const std::string &output_directory,
                     const MPI_Comm     comm) override;

    bool
    writes_files() const override
    {
      return all || !increments.empty();
    }

    /// "FCLIB problems of increments 1, 3 (fclib-NNNNN.hdf5)", or "".
    std::string
    describe() const override;

    /// Throws an InputError if an increment named is past the last of a
    /// loading history of @p n_increments.
    void
    check_scene(const unsigned int n_increments,
                const Model<dim>  &model) const override;

    Postprocess::Columns
    execute(const Postprocess::IncrementResult<dim> &result) override;

    void
    execute_failed(const Postprocess::IncrementResult<dim> &result) override;

  private:
    /// Writes the increment of @p result if it is wanted; with the solution
    /// if @p converged. Collective.
    void
    write(const Postprocess::IncrementResult<dim> &result,
          const bool                               converged) const;

    /// The file of increment @p increment.
    std::string
    file_name(const unsigned int increment) const;

    std::string            directory;
    std::string            text;
    bool                   all = false;
    std::set<unsigned int> increments;
  };
} // namespace FrictionalContact
