#include <frictional_contact/base/plugins.h>
#include <frictional_contact/postprocess/interface.h>

namespace FrictionalContact
{
  namespace Postprocess
  {
    /// The columns of the contact solve: iterations, linear iterations,
    /// AMG set-ups and updates, wall time and the paper's three residuals.
    template <int dim>
    class SolverStatistics : public Interface<dim>
    {
    public:
      unsigned int
      default_position() const override
      {
        return 1;
      }

      Columns
      execute(const IncrementResult<dim> &result) override
      {
        const SolveStatistics &solve = result.outcome.statistics;
        return {{"Contact solver iterations", std::uint64_t(solve.iterations)},
                {"Krylov iterations", std::uint64_t(solve.linear_iterations)},
                {"AMG setups", std::uint64_t(solve.amg_setups)},
                {"AMG updates", std::uint64_t(solve.amg_updates)},
                {"Solve wall time (s)", solve.seconds},
                {"Force balance residual", solve.residuals.force_balance, true},
                {"Complementarity residual",
                 solve.residuals.complementarity,
                 true},
                {"Penetration residual", solve.residuals.penetration, true}};
      }
    };

    FRICTIONAL_CONTACT_REGISTER_PLUGIN(
      Interface,
      SolverStatistics,
      "solver statistics",
      "Statistics columns of the contact solve: its iterations, the Krylov "
      "iterations of its linear solves (column 'Krylov iterations': CG, or GMRES "
      "when a node slips), AMG set-ups, AMG updates (the Newton method's "
      "preconditioner made again for new node conditions, its coarse levels "
      "only), wall time and the three residuals.")
  } // namespace Postprocess
} // namespace FrictionalContact
