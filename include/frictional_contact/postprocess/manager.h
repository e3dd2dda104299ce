#pragma once

#include <deal.II/base/parameter_handler.h>

#include <frictional_contact/postprocess/interface.h>

#include <memory>
#include <string>
#include <vector>

namespace FrictionalContact
{
  namespace Postprocess
  {
    /**
     * Runs the postprocessors after every increment and keeps the
     * statistics file: one row per increment, made of the increment's own
     * columns and those the postprocessors return, rewritten (atomically,
     * by rank 0) after every increment so that an interrupted run keeps all
     * finished rows (a resumed run keeps those of its checkpoint). Owns
     * the subsection "Output": its own entries, the
     * checkpoint cadence, and those of every postprocessor.
     */
    template <int dim>
    class Manager
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      Manager(ParameterHandler  &prm,
              const std::string &output_directory,
              const MPI_Comm     comm);

      /// Throws an InputError if a postprocessor cannot work with
      /// @p n_increments.
      void
      check_scene(const unsigned int n_increments, const Model<dim> &model) const;

      /// Every file a run of @p n_increments writes ("vtu every increment
      /// (solution/, solution.pvd), statistics, parameters.prm"), or "" if
      /// nothing is written.
      std::string
      describe(const unsigned int n_increments) const;

      /// Whether a checkpoint is due after increment @p increment (from 1)
      /// of @p n_increments.
      bool
      checkpoint_due(const unsigned int increment,
                     const unsigned int n_increments) const;

      /// Whether anything is written into the output directory.
      bool
      writes_files() const;

      /// Whether a postprocessor needs the contact solver's iterations.
      bool
      needs_history() const;

      /// Runs every postprocessor and writes the statistics row.
      void
      execute(const IncrementResult<dim> &result);

      /// Lets the postprocessors record an increment that failed.
      void
      execute_failed(const IncrementResult<dim> &result);

      /// The rows so far and the postprocessors' states, for checkpoints.
      std::string
      save_state() const;

      void
      load_state(const std::string &state);

    private:
      std::vector<std::unique_ptr<Interface<dim>>> postprocessors;
      bool                                         write_statistics;
      std::string                                  statistics_file;
      unsigned int                                 checkpoint_every;
      MPI_Comm                                     comm;
      StatisticsTable                              statistics;
    };
  } // namespace Postprocess
} // namespace FrictionalContact
