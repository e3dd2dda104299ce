#include <frictional_contact/base/input.h>
#include <frictional_contact/postprocess/screen_report.h>

#include <iomanip>
#include <sstream>

namespace FrictionalContact
{
  namespace Postprocess
  {
    namespace
    {
      /// "(0, -0.01)"
      template <int dim>
      std::string
      vector_text(const Tensor<1, dim> &v)
      {
        std::string text = "(";
        for (unsigned int d = 0; d < dim; ++d)
          text += (d == 0 ? "" : ", ") + Input::to_text(v[d]);
        return text + ")";
      }

      std::string
      percent(const unsigned int part, const types::global_dof_index whole)
      {
        std::ostringstream out;
        out << std::fixed << std::setprecision(1)
            << (whole > 0 ? 100. * part / whole : 0.) << '%';
        return out.str();
      }

      /// The deepest penetration the solver allows a candidate: the
      /// penetration residual (a Euclidean norm over the candidates, so at
      /// least the deepest one) plus 1e-10 times the increment's length.
      template <int dim>
      double
      allowed_penetration(const IncrementResult<dim> &result)
      {
        const auto &problem = result.outcome.problem;
        return result.outcome.statistics.residuals.penetration +
               (problem ? 1e-10 * problem->length_scale : 0.);
      }

      std::string
      residual_text(const Residuals &res)
      {
        return Input::scientific(res.force_balance) + ' ' +
               Input::scientific(res.complementarity) + ' ' +
               Input::scientific(res.penetration);
      }
    } // namespace



    template <int dim>
    void
    print_increment(const ConditionalOStream   &out,
                    const IncrementResult<dim> &result,
                    const std::string          &iteration_name,
                    const std::string          &last_linear_solve)
    {
      const SolveStatistics     &solve   = result.outcome.statistics;
      const ContactSummary<dim> &summary = result.summary;
      const bool contact = result.model.get_contact().active();
      out << "Increment " << result.increment << "/" << result.n_increments
          << ", t = " << Input::to_text(result.time);
      if (contact && solve.iterations == 0)
        out << ": nothing touches, the elastic solution ("
            << solve.linear_iterations << " CG iterations); residuals "
            << residual_text(solve.residuals) << std::endl;
      else if (contact)
        out << ": " << solve.iterations << ' ' << iteration_name
            << " iterations, " << solve.linear_iterations
            << " Krylov iterations, "
            << solve.amg_setups << " AMG set-ups; residuals "
            << residual_text(solve.residuals) << "; free/stick/slip "
            << summary.count(ContactState::free) << '/'
            << summary.count(ContactState::stick) << '/'
            << summary.count(ContactState::slip) << std::endl;
      else if (result.model.nonlinear())
        out << ": " << solve.iterations << ' ' << iteration_name
            << " iterations, " << solve.linear_iterations
            << " Krylov iterations; force balance residual "
            << Input::scientific(solve.residuals.force_balance) << std::endl;
      else
        out << ": elastic solve, " << solve.linear_iterations
            << " " << last_linear_solve << std::endl;
      if (result.outcome.geometry_passes > 0)
        out << "    contact pairs' geometry: " << result.outcome.geometry_passes
            << " solve" << (result.outcome.geometry_passes > 1 ? "s" : "")
            << ", normals settled to "
            << Input::scientific(result.outcome.geometry_change) << std::endl;
      // The candidates' penetration is bounded by the residual; a vertex
      // that is not a candidate must not go deeper.
      if (contact && summary.deepest_penetration > allowed_penetration(result))
        out << "Warning: a vertex of the contact boundary is "
            << Input::scientific(summary.deepest_penetration)
            << " inside the obstacle, deeper than the solver allows any "
               "contact candidate (penetration residual "
            << Input::scientific(solve.residuals.penetration) << ")"
            << std::endl;
      out << "-- increment " << result.increment << " solve wall time "
          << solve.seconds << " s" << std::endl;
    }



    template <int dim>
    void
    print_final_state(const ConditionalOStream &out, const IncrementResult<dim> &result)
    {
      const Model<dim>          &model   = result.model;
      const ElasticBody<dim>    &body    = model.get_body();
      const Residuals           &res     = result.outcome.statistics.residuals;
      const ContactSummary<dim> &summary = result.summary;

      TrilinosWrappers::MPI::Vector u_ghosted = body.make_ghosted_vector();
      u_ghosted                               = result.state.u;
      const Tensor<1, dim> support =
        model.support_reaction(u_ghosted, result.load_factor);
      const Tensor<1, dim> load = result.load_factor * body.total_load();
      const types::global_dof_index c = model.get_contact().n_candidates();
      const unsigned int free  = summary.count(ContactState::free);
      const unsigned int slip  = summary.count(ContactState::slip);
      const unsigned int stick = summary.count(ContactState::stick);
      out << "State at t = " << Input::to_text(result.time) << ":" << std::endl;
      if (model.get_contact().active())
        out << "    residuals: force balance "
            << Input::scientific(res.force_balance) << ", complementarity "
            << Input::scientific(res.complementarity) << ", penetration "
            << Input::scientific(res.penetration) << std::endl
            << "    candidates: " << percent(free, c) << " free, "
            << percent(stick, c) << " stick, " << percent(slip, c)
            << " slip (" << free << " / " << stick << " / " << slip << " of "
            << c << ")" << std::endl;
      out << "    force balance: load " << vector_text(load) << " + contact "
          << vector_text(summary.external_force) << " + supports "
          << vector_text(support) << " = "
          << Input::scientific((load + summary.external_force + support).norm())
          << std::endl
          << "    max |u| = "
          << Input::to_text(body.largest_nodal_magnitude(result.state.u))
          << std::endl;
      if (model.get_contact().active())
        out << "    contact boundary: deepest penetration of any vertex "
            << Input::scientific(summary.deepest_penetration) << std::endl;
    }

    template void
    print_increment(const ConditionalOStream &,
                    const IncrementResult<2> &,
                    const std::string &,
                    const std::string &);
    template void
    print_increment(const ConditionalOStream &,
                    const IncrementResult<3> &,
                    const std::string &,
                    const std::string &);
    template void
    print_final_state(const ConditionalOStream &, const IncrementResult<2> &);
    template void
    print_final_state(const ConditionalOStream &, const IncrementResult<3> &);
  } // namespace Postprocess
} // namespace FrictionalContact
