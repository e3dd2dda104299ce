#pragma once

#include <deal.II/base/parameter_handler.h>

#include <frictional_contact/driver/increment_solver.h>
#include <frictional_contact/model/model.h>
#include <frictional_contact/postprocess/contact_summary.h>
#include <frictional_contact/postprocess/statistics_table.h>

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace FrictionalContact
{
  namespace Postprocess
  {
    /// What an increment leaves for the postprocessors.
    template <int dim>
    struct IncrementResult
    {
      /// Counted from 1, of n_increments.
      unsigned int                 increment;
      unsigned int                 n_increments;
      double                       time;
      double                       load_factor;
      const Model<dim>            &model;
      /// The state after the increment (before it, if it failed).
      const State<dim>            &state;
      const IncrementOutcome<dim> &outcome;
      /// Counts, forces and areas of the contact (zero if it failed).
      const ContactSummary<dim> &summary;

      bool
      last() const
      {
        return increment == n_increments;
      }
    };

    /**
     * A postprocessor in the sense of ASPECT: after each increment it
     * writes what it is for and returns its columns of the statistics
     * file. Postprocessors register themselves with
     * FRICTIONAL_CONTACT_REGISTER_PLUGIN(Postprocess::Interface, ...) and
     * run in the order of <Postprocess/List of postprocessors>; each
     * declares its entries in its own subsection of "Postprocess", named
     * like it ("visualization": "Postprocess/Visualization"), as ASPECT's
     * do.
     */
    template <int dim>
    class Interface
    {
    public:
      virtual ~Interface() = default;

      /// Where it stands in the default <Postprocess/List of
      /// postprocessors> (which orders the statistics columns), counted
      /// from 1; 0: not in the default list.
      virtual unsigned int
      default_position() const = 0;

      /// Declares its entries (inside its subsection); none by default.
      static void
      declare_parameters(ParameterHandler &)
      {}

      /// Reads its entries (inside its subsection); @p directory is where it
      /// writes. Nothing by default.
      virtual void
      parse_parameters(ParameterHandler & /*prm*/,
                       const std::string & /*directory*/,
                       const MPI_Comm /*comm*/)
      {}

      /// What it writes ("vtu every increment"), or "" if nothing.
      virtual std::string
      describe() const
      {
        return "";
      }

      /// Whether it writes files into the output directory.
      virtual bool
      writes_files() const
      {
        return !describe().empty();
      }

      /// Whether it needs the contact solver's iterations recorded.
      virtual bool
      needs_history() const
      {
        return false;
      }

      /// Throws an InputError if it cannot work with @p n_increments
      /// increments of @p model (before anything is written).
      virtual void
      check_scene(const unsigned int /*n_increments*/,
                  const Model<dim> & /*model*/) const
      {}

      /// Writes what it writes for a converged increment; returns its columns.
      virtual Columns
      execute(const IncrementResult<dim> &result) = 0;

      /// Called for an increment whose contact solve did not converge,
      /// before the run stops or cuts it.
      virtual void
      execute_failed(const IncrementResult<dim> & /*result*/)
      {}

      /// What a checkpoint keeps of it (the files written so far, say).
      virtual std::string
      save_state() const
      {
        return "";
      }

      virtual void
      load_state(const std::string & /*state*/)
      {}
    };
  } // namespace Postprocess
} // namespace FrictionalContact
