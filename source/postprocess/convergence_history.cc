#include <frictional_contact/base/files.h>
#include <frictional_contact/base/plugins.h>
#include <frictional_contact/postprocess/interface.h>

#include <iomanip>
#include <sstream>

namespace FrictionalContact
{
  namespace Postprocess
  {
    /// history-NNNNN.txt per increment: one row per contact-solver iteration.
    template <int dim>
    class ConvergenceHistory : public Interface<dim>
    {
    public:
      unsigned int
      default_position() const override
      {
        return 5;
      }

      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Write convergence history",
                          "false",
                          Patterns::Bool(),
                          "Write history-NNNNN.txt for each increment: one "
                          "row per iteration of the contact solver with the "
                          "wall time, the three residuals, |du_k+1 - du_k|, "
                          "the Krylov iterations, and for the Newton method "
                          "the candidates that changed their free/stick/slip "
                          "condition and the forcing term (see "
                          "scripts/plot_history.py).");
      }

      void
      parse_parameters(ParameterHandler  &prm,
                       const std::string &output_directory,
                       const MPI_Comm     comm) override
      {
        enabled         = prm.get_bool("Write convergence history");
        directory       = output_directory;
        this->comm      = comm;
      }

      std::string
      describe() const override
      {
        return enabled ? "convergence histories (history-NNNNN.txt)" : "";
      }

      bool
      needs_history() const override
      {
        return enabled;
      }

      Columns
      execute(const IncrementResult<dim> &result) override
      {
        const std::vector<HistoryRow> &history =
          result.outcome.statistics.history;
        if (!enabled || history.empty())
          return {};
        run_on_root(comm, [&]() {
          std::ostringstream text;
          text << "# Convergence history of increment " << result.increment
               << " (t = " << result.time << "): one row per iteration of "
               << "the contact solver.\n"
               << "# iteration seconds force_balance complementarity "
                  "penetration step linear_iterations active_set_changes "
                  "forcing_term active_nodes plastic_points\n"
               << std::setprecision(9);
          for (const HistoryRow &row : history)
            text << row.iteration << ' ' << row.seconds << ' '
                 << row.residuals.force_balance << ' '
                 << row.residuals.complementarity << ' '
                 << row.residuals.penetration << ' ' << row.step << ' '
                 << row.linear_iterations << ' ' << row.active_set_changes
                 << ' ' << row.forcing_term << ' ' << row.active_nodes << ' '
                 << row.plastic_points << '\n';
          std::ostringstream name;
          name << directory << "/history-" << std::setw(5) << std::setfill('0')
               << result.increment << ".txt";
          write_file_atomically(name.str(), text.str());
        });
        return {};
      }

    private:
      bool        enabled = false;
      std::string directory;
      MPI_Comm    comm = MPI_COMM_WORLD;
    };

    FRICTIONAL_CONTACT_REGISTER_PLUGIN(
      Interface,
      ConvergenceHistory,
      "convergence history",
      "history-NNNNN.txt per increment, if Write convergence history is "
      "set: the residuals of every iteration of the contact solver against "
      "wall time.")
  } // namespace Postprocess
} // namespace FrictionalContact
