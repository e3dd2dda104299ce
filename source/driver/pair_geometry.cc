#include <deal.II/lac/full_matrix.h>

#include <frictional_contact/driver/pair_geometry.h>

#include <deque>

namespace FrictionalContact
{
  namespace
  {
    /// The passes whose differences Anderson's mixing combines.
    constexpr unsigned int anderson_depth = 3;

    /// A pass before the last stops at this fraction of the last change
    /// of the geometry (relative, as the Newton tolerance is).
    constexpr double looseness = 1e-3;

    /**
     * Anderson's mixing for a fixed point x = g(x) of vectors (Walker and
     * Ni, 2011), with the differences of the last few passes: from x_k and
     * g(x_k), x_k+1 = g(x_k) - sum_i gamma_i (g_i+1 - g_i), where gamma
     * minimises |f_k - sum_i gamma_i (f_i+1 - f_i)| over the residuals
     * f = g(x) - x. Owns those differences.
     */
    class AndersonMixing
    {
    public:
      using Vector = TrilinosWrappers::MPI::Vector;

      explicit AndersonMixing(const unsigned int depth)
        : depth(depth)
      {}

      /// Replaces @p x (x_k) by x_k+1, given @p g = g(x_k). Collective.
      void
      next(const Vector &g, Vector &x)
      {
        Vector f = g;
        f -= x;
        if (last_f.size() > 0)
          {
            residual_changes.push_back(f);
            residual_changes.back() -= last_f;
            image_changes.push_back(g);
            image_changes.back() -= last_g;
            if (residual_changes.size() > depth)
              {
                residual_changes.pop_front();
                image_changes.pop_front();
              }
          }
        last_f = f;
        last_g = g;
        x      = g;
        const unsigned int m = residual_changes.size();
        if (m == 0)
          return;
        // The normal equations of the small least-squares problem, with
        // a relative shift against round-off in nearly parallel columns.
        FullMatrix<double> A(m, m);
        std::vector<double> rhs(m);
        double             largest = 0;
        for (unsigned int i = 0; i < m; ++i)
          {
            for (unsigned int j = 0; j <= i; ++j)
              A(i, j) = A(j, i) = residual_changes[i] * residual_changes[j];
            rhs[i]  = residual_changes[i] * f;
            largest = std::max(largest, A(i, i));
          }
        if (!(largest > 0))
          return;
        for (unsigned int i = 0; i < m; ++i)
          A(i, i) += 1e-12 * largest;
        A.gauss_jordan();
        for (unsigned int i = 0; i < m; ++i)
          {
            double gamma = 0;
            for (unsigned int j = 0; j < m; ++j)
              gamma += A(i, j) * rhs[j];
            x.add(-gamma, image_changes[i]);
          }
      }

    private:
      const unsigned int depth;
      std::deque<Vector> residual_changes, image_changes;
      /// f and g of the last pass (empty before the first).
      Vector last_f, last_g;
    };
  } // namespace



  template <int dim>
  IncrementOutcome<dim>
  solve_with_settled_pair_geometry(
    Model<dim>                                   &model,
    const TrilinosWrappers::MPI::Vector          &u,
    const double                                  t_start,
    const double                                  t_end,
    const std::function<IncrementOutcome<dim>(const WarmStart<dim> *)> &solve_once)
  {
    ContactOperator<dim> &contact = model.get_contact();
    if (!contact.has_pairs())
      return solve_once(nullptr);
    const double       tolerance  = contact.pair_passes_settings().tolerance;
    const unsigned int max_passes = contact.pair_passes_settings().max_passes;

    // The configuration the increment starts from: the state and the
    // increment of the prescribed displacements.
    const ElasticBody<dim>       &body  = model.get_body();
    TrilinosWrappers::MPI::Vector start = body.make_vector();
    body.prescribed_increment(t_start, t_end, start);
    start += u;
    TrilinosWrappers::MPI::Vector start_ghosted = body.make_ghosted_vector();
    start_ghosted = start;
    contact.update_pairs(body, start_ghosted, t_start, t_end);
    IncrementOutcome<dim> outcome = solve_once(nullptr);
    if (!contact.pairs_follow_configuration())
      return outcome;

    // The configuration x whose geometry the last solve had, and where
    // that solve ended, s: the fixed point x = s, accelerated by
    // Anderson's mixing of the last passes.
    SolveStatistics               work = outcome.statistics;
    TrilinosWrappers::MPI::Vector taken = start, reached = start;
    TrilinosWrappers::MPI::Vector ghosted = body.make_ghosted_vector();
    AndersonMixing                mixing(anderson_depth);
    // Each solve starts from the last one's solution (its forces in
    // Cartesian components, before the frames change).
    WarmStart<dim> warm_start{body.make_vector(), {}};
    for (unsigned int pass = 1; outcome.statistics.converged; ++pass)
      {
        warm_start.forces.resize(contact.n_local());
        for (unsigned int j = 0; j < contact.n_local(); ++j)
          warm_start.forces[j] = contact.to_cartesian(j, outcome.reactions[j]);
        reached = u;
        reached += outcome.du;
        warm_start.du = reached;
        warm_start.du -= start;
        ghosted = reached;
        contact.update_pairs(body, ghosted, t_start, t_end, &start_ghosted);
        const auto &change = contact.last_pair_change();
        outcome.geometry_passes = pass;
        outcome.geometry_change = change.normal;
        // Gaps are measured against the displacement so far: an
        // increment cut small does not ask for a smaller change.
        const double relative_gap_change = change.gap / reached.linfty_norm();
        const bool   settled = change.normal <= tolerance && relative_gap_change <= tolerance;
        if (settled && outcome.statistics.loosened && pass < max_passes)
          {
            // Settled on a solve stopped short: once more to the method's
            // tolerance, on the geometry where it ended.
            taken                = reached;
            warm_start.tolerance = 0;
            outcome              = solve_once(&warm_start);
            work.add_work(outcome.statistics);
            continue;
          }
        if (settled || pass == max_passes)
          {
            const SolveStatistics last = outcome.statistics;
            outcome.statistics           = work;
            outcome.statistics.converged = settled;
            outcome.statistics.residuals = last.residuals;
            outcome.statistics.history   = last.history;
            if (!settled)
              outcome.statistics.failure =
                "the contact pairs' geometry did not settle in " +
                std::to_string(max_passes) +
                " solves (<Contact/Pair geometry/Maximum passes>): the last "
                "solve still turned a normal by " +
                Input::scientific(change.normal) + " and moved a gap by " +
                Input::scientific(change.gap) +
                "; try smaller increments or <Loading/On failure> = cut "
                "increment";
            return outcome;
          }
        mixing.next(reached, taken);
        ghosted = taken;
        contact.update_pairs(body, ghosted, t_start, t_end, &start_ghosted);
        // While the geometry still moves, the solve need not be more
        // accurate than a fraction of that move.
        warm_start.tolerance =
          looseness * std::max(change.normal, relative_gap_change);
        outcome = solve_once(&warm_start);
        work.add_work(outcome.statistics);
      }
    return outcome;
  }

  template IncrementOutcome<2>
  solve_with_settled_pair_geometry(
    Model<2> &, const TrilinosWrappers::MPI::Vector &, const double, const double,
    const std::function<IncrementOutcome<2>(const WarmStart<2> *)> &);
  template IncrementOutcome<3>
  solve_with_settled_pair_geometry(
    Model<3> &, const TrilinosWrappers::MPI::Vector &, const double, const double,
    const std::function<IncrementOutcome<3>(const WarmStart<3> *)> &);
} // namespace FrictionalContact
