#pragma once

#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <frictional_contact/solvers/contact_problem.h>
#include <frictional_contact/solvers/progress_rules.h>
#include <frictional_contact/solvers/volumetric_split.h>

#include <array>
#include <functional>
#include <limits>
#include <vector>

namespace FrictionalContact
{
  /**
   * The building blocks of SemismoothNewtonSolver: the node conditions of
   * one Newton iteration and how the candidates are sorted into them, the
   * linear operator with the conditions imposed by projection, the merit of
   * the line search, and the Krylov solve of the linear problem.
   */
  namespace SemismoothNewton
  {
    using Vector = TrilinosWrappers::MPI::Vector;

    /// What the linear problem of a Newton iteration prescribes at a node.
    enum class NodeCondition : unsigned char
    {
      none,         // free: no force
      normal_fixed, // slip: normal displacement fixed, friction force given
      all_fixed     // stick: normal and tangential displacement fixed
    };

    /**
     * The projections of the node conditions. apply(), on forces: the
     * orthogonal projection that removes the normal part at slipping nodes
     * and the whole nodal vector at sticking ones (the reactions take
     * them). apply_to_step(), on Newton steps: onto the steps that keep the
     * conditions, the whole nodal vector removed at sticking nodes, and at
     * slipping ones the normal part that keeps the gap closed as the node
     * slides (IncrementalProblem::gap_slopes): zero where the gap does not
     * change with the slide, else a step oblique to the normal, its
     * tangential part free.
     */
    template <int dim>
    class NodeProjection
    {
    public:
      NodeProjection(const ContactMap<dim>             &contact,
                     const std::vector<NodeCondition> &conditions,
                     const std::vector<Tensor<1, dim>> &gap_slopes)
        : contact(contact)
        , conditions(conditions)
        , gap_slopes(gap_slopes)
      {}

      void
      apply(Vector &v) const
      {
        for (unsigned int j = 0; j < contact.n_local(); ++j)
          if (conditions[j] != NodeCondition::none)
            {
              Tensor<1, dim> fixed_part = contact.local_part(j, v);
              if (conditions[j] == NodeCondition::normal_fixed)
                for (unsigned int d = 1; d < dim; ++d)
                  fixed_part[d] = 0;
              contact.add_reaction(j, -fixed_part, v);
            }
      }

      void
      apply_to_step(Vector &v) const
      {
        if (gap_slopes.empty())
          {
            apply(v);
            return;
          }
        for (unsigned int j = 0; j < contact.n_local(); ++j)
          if (conditions[j] != NodeCondition::none)
            {
              const Tensor<1, dim> part = contact.local_part(j, v);
              Tensor<1, dim>       removed = part;
              if (conditions[j] == NodeCondition::normal_fixed)
                {
                  // approach(j, part - removed) = 0 with part's tangent.
                  Tensor<1, dim> tangential = part;
                  tangential[0]             = 0;
                  removed                   = Tensor<1, dim>();
                  removed[0] = part[0] - gap_slopes[j] * tangential /
                                           (1. - gap_slopes[j][0]);
                }
              contact.add_reaction(j, -removed, v);
            }
      }

    private:
      const ContactMap<dim>             &contact;
      const std::vector<NodeCondition> &conditions;
      const std::vector<Tensor<1, dim>> &gap_slopes;
    };

    /**
     * The Newton operator on the subspace of the node conditions:
     * w -> P ((I + C) (K + S) w + B w), S the stabilisation of bodies that
     * only contact holds (ContactHeldBodies; zero for most scenes). C couples the friction force of a
     * slipping node to its normal reaction, so that its tangential equation
     * reads T_t^T R + mu n (t_n^T R) + kappa Q T_t^T du = 0 with R = K du - p:
     * r_t = -mu r_n n - kappa Q u_t, the linearisation of
     * r_t = mu |r_n| zeta / |zeta| (Q = I - n n^T, the tangential directions
     * across the slip; B is this Robin term, zero in 2D). Where the frames
     * follow the configuration, K has the stiffness of the turning frames
     * at the nodes in contact (ContactMap::add_frame_stiffness(),
     * from @p reactions; nullptr for fixed frames). Without slipping nodes
     * the operator is P K P, symmetric.
     */
    template <int dim>
    class ContactStiffness
    {
    public:
      ContactStiffness(const StiffnessOperator &K,
                       const NodeProjection<dim>            &P,
                       const ContactMap<dim>                 &contact,
                       const std::vector<NodeCondition>     &conditions,
                       const std::vector<Tensor<1, dim>>    &slip_direction,
                       const std::vector<double>            &robin,
                       const bool                            friction,
                       const Vector                         &stabilization,
                       const std::vector<Tensor<1, dim>>    *reactions = nullptr)
        : K(K)
        , P(P)
        , contact(contact)
        , conditions(conditions)
        , slip_direction(slip_direction)
        , robin(robin)
        , friction(friction)
        , stabilization(stabilization)
        , frames_turn(reactions != nullptr)
      {
        // The reactions that act: none at a free node.
        if (frames_turn)
          {
            acting = *reactions;
            for (unsigned int j = 0; j < acting.size(); ++j)
              if (conditions[j] == NodeCondition::none)
                acting[j] = Tensor<1, dim>();
          }
      }

      void
      vmult(Vector &dst, const Vector &src) const
      {
        K.vmult(dst, src);
        finish(dst, src);
      }

      /// The operator from the force K u in @p force: the stabilisation,
      /// the coupling, the Robin term of @p u, the projection.
      void
      finish(Vector &force, const Vector &u) const
      {
        if (stabilization.size() > 0)
          {
            const double *S = stabilization.begin();
            const double *x = u.begin();
            double       *f = force.begin();
            for (unsigned int i = 0; i < force.locally_owned_size(); ++i)
              f[i] += S[i] * x[i];
          }
        if (frames_turn)
          contact.add_frame_stiffness(acting, u, force);
        couple(force);
        add_robin(u, 1., force);
        P.apply(force);
      }

      /// v += C v: the friction force that goes with the normal reaction.
      void
      couple(Vector &v) const
      {
        if (!friction)
          return;
        for (unsigned int j = 0; j < contact.n_local(); ++j)
          if (conditions[j] == NodeCondition::normal_fixed)
            {
              const double r_n = contact.local_part(j, v)[0];
              contact.add_reaction(j,
                                   contact.friction_coefficient(j) * r_n *
                                     slip_direction[j],
                                   v);
            }
      }

      /// dst += factor B u.
      void
      add_robin(const Vector &u, const double factor, Vector &dst) const
      {
        if (!friction || dim == 2)
          return;
        for (unsigned int j = 0; j < contact.n_local(); ++j)
          if (conditions[j] == NodeCondition::normal_fixed && robin[j] > 0)
            {
              Tensor<1, dim> u_t = contact.local_part(j, u);
              u_t[0]             = 0;
              u_t -= (u_t * slip_direction[j]) * slip_direction[j];
              contact.add_reaction(j, factor * robin[j] * u_t, dst);
            }
      }

    private:
      const StiffnessOperator &K;
      const NodeProjection<dim>            &P;
      const ContactMap<dim>                 &contact;
      const std::vector<NodeCondition>     &conditions;
      const std::vector<Tensor<1, dim>>    &slip_direction;
      const std::vector<double>            &robin;
      /// Whether the slipping nodes carry their friction (mu_j of each
      /// node's pair) or, in the frictionless start, none.
      const bool                            friction;
      /// The diagonal of S (empty: none).
      const Vector                         &stabilization;
      /// Whether the frames follow the configuration, and then the
      /// reactions of the iterate that act (zero at a free node).
      const bool                            frames_turn;
      std::vector<Tensor<1, dim>>           acting;
    };

    /// The node conditions of an active-set step and what goes with them.
    template <int dim>
    struct ActiveSets
    {
      explicit ActiveSets(const std::vector<double> &c_t)
        : conditions(c_t.size(), NodeCondition::none)
        , bound(c_t.size(), 0.)
        , slip_direction(c_t.size())
        , robin(c_t.size(), 0.)
        , c_t(c_t)
        , smallest_c_t(c_t)
        , flips(c_t.size(), 0)
      {
        for (double &c_t_j : smallest_c_t)
          c_t_j *= smallest_c_t_fraction;
      }

      /**
       * How far the anti-cycling may lower c_t: to this fraction of its
       * first value (two tenfold cuts). A node that slid far in the
       * increment and whose c_t had been cut without a floor (to 1e-12 of
       * c_j in the 3D ironing) was sorted by a force a hair inside the cone
       * alone: sticking, the Newton step pulled it back by the whole slide,
       * and the merit rose hundreds of times along the step.
       */
      static constexpr double smallest_c_t_fraction = 0.01;

      std::vector<NodeCondition>  conditions;
      /// mu max(sigma_j, 0): the friction bound of each node.
      std::vector<double>         bound;
      std::vector<Tensor<1, dim>> slip_direction;
      /// kappa_j of the Robin term across the slip (3D).
      std::vector<double>         robin;
      /// c_t per node, and how often its stick/slip state went back and
      /// forth.
      std::vector<double>       c_t;
      /// The floor of c_t per node (smallest_c_t_fraction of the first).
      std::vector<double>       smallest_c_t;
      std::vector<unsigned int> flips;
    };

    /**
     * Sorts the nodes by the augmented reactions of (du, r): free where the
     * augmented normal reaction sigma_j is not positive, stick inside the
     * friction bound, slip on it. Returns how many nodes of this rank
     * changed their condition.
     */
    template <int dim>
    unsigned int
    classify(const IncrementalProblem<dim>     &problem,
             const Vector                      &du,
             const std::vector<Tensor<1, dim>> &r,
             const std::vector<double>         &c,
             const bool                         friction,
             ActiveSets<dim>                   &sets)
    {
      const unsigned int n       = c.size();
      unsigned int       changes = 0;
    for (unsigned int j = 0; j < n; ++j)
      {
        const Tensor<1, dim> u_j = problem.relative_displacement(j, du);
        const double sigma =
          -r[j][0] - c[j] * (problem.gaps[j] - problem.approach(j, u_j));
        Tensor<1, dim> zeta = r[j] - sets.c_t[j] * u_j;
        zeta[0]             = 0;
        const double zeta_norm = zeta.norm();
        const NodeCondition before = sets.conditions[j];
        const Tensor<1, dim> direction_before = sets.slip_direction[j];
        const double mu_j =
          friction ? problem.contact.friction_coefficient(j) : 0.;
        sets.bound[j] = mu_j * std::max(sigma, 0.);
        if (!(sigma > 0))
          sets.conditions[j] = NodeCondition::none;
        else if (mu_j > 0 && zeta_norm < sets.bound[j])
          sets.conditions[j] = NodeCondition::all_fixed;
        else
          {
            sets.conditions[j] = NodeCondition::normal_fixed;
            sets.slip_direction[j] =
              zeta_norm > 0 ? zeta / zeta_norm : Tensor<1, dim>();
            // kappa = s c_t / (|zeta| - s), bounded where |zeta| ~ s.
            sets.robin[j] = zeta_norm > sets.bound[j] ?
                         std::min(sets.bound[j] * sets.c_t[j] / (zeta_norm - sets.bound[j]),
                                  1e3 * c[j]) :
                         0.;
          }
        if (sets.conditions[j] != before)
          ++changes;
        // Anti-cycling: stick <-> slip, or a reversed slip direction.
        const bool flipped =
          before != NodeCondition::none &&
          sets.conditions[j] != NodeCondition::none &&
          (sets.conditions[j] != before ||
           (before == NodeCondition::normal_fixed &&
            sets.slip_direction[j] * direction_before < 0));
        if (mu_j > 0 && flipped && ++sets.flips[j] >= 2)
          {
            sets.c_t[j] = std::max(0.1 * sets.c_t[j], sets.smallest_c_t[j]);
            sets.flips[j] = 0;
          }
      }
      return changes;
    }



    /**
     * The merit of the line search at the point t of the segment from the
     * previous iterate (du_0, r_0) to the new one (du_1, r_1): the squared
     * complementarity functions of all nodes, scaled by c_j, plus the
     * squared force balance residual, scaled by the mean c. For a linear
     * law the residual and the reactions are linear along the segment. For
     * a nonlinear one, @p nonlinear_residual gives the residual at t,
     * N(du) - p - T ((1 - t) r_0 + t r_1) (nullptr where a cell inverts),
     * and the reactions of the nodes in contact (@p conditions) take, as r_1
     * did at t = 1, its part that the straight line misses, N(du) - (1 - t)
     * N(du_0) - t N(du_1): with the reactions interpolated alone, a long
     * Newton step's curvature entered every short step's merit to first
     * order, and the merit rose along steps that descend. Collective.
     */
    template <int dim>
    class MeritAlongStep
    {
    public:
      MeritAlongStep(const IncrementalProblem<dim>     &problem,
                     const std::vector<NodeCondition>  &conditions,
                     const std::vector<double>         &c,
                     const std::vector<double>         &c_t,
                     const bool                         friction,
                     const double                       mean_c,
                     const Vector                      &du_0,
                     const Vector                      &du_1,
                     const std::vector<Tensor<1, dim>> &r_0,
                     const std::vector<Tensor<1, dim>> &r_1,
                     const Vector                      &balance_0,
                     const Vector                      &balance_1,
                     Vector                            &scratch,
                     std::function<const Vector *(double)> nonlinear_residual = {})
        : problem(problem)
        , conditions(conditions)
        , c(c)
        , c_t(c_t)
        , friction(friction)
        , mean_c(mean_c)
        , du_0(du_0)
        , du_1(du_1)
        , r_0(r_0)
        , r_1(r_1)
        , scratch(scratch)
        , nonlinear_residual(std::move(nonlinear_residual))
      {
        // The nodes in contact's parts of both ends' residuals, for the
        // reactions the straight line misses (nonlinear laws).
        if (this->nonlinear_residual)
          {
            balance_at_nodes.resize(c.size());
            for (unsigned int j = 0; j < c.size(); ++j)
              if (conditions[j] != NodeCondition::none)
                balance_at_nodes[j] = {{problem.contact.local_part(j, balance_0),
                                        problem.contact.local_part(j, balance_1)}};
          }
        // Frames that follow the configuration turn along the step as the
        // Newton tangent has them turn (to first order).
        if (problem.contact.frames_follow_configuration() || problem.pair_frame_turns)
          {
            scratch = du_1;
            scratch -= du_0;
            if (problem.pair_frame_turns)
              problem.pair_frame_turns(scratch, step_turns);
            else
              problem.contact.normal_turns(scratch, step_turns);
          }
        balance_a = balance_0.norm_sqr();
        balance_b = balance_0 * balance_1 - balance_a;
        scratch   = balance_1;
        scratch -= balance_0;
        balance_c = scratch.norm_sqr();
      }

      double
      operator()(const double t) const
      {
        const bool    inside   = nonlinear_residual && t > 0 && t < 1;
        const Vector *residual = inside ? nonlinear_residual(t) : nullptr;
        if (inside && residual == nullptr)
          return std::numeric_limits<double>::infinity();
        if (inside)
          scratch = *residual;
        double sum = 0;
        for (unsigned int j = 0; j < c.size(); ++j)
          {
            Tensor<1, dim> missed;
            if (inside && conditions[j] != NodeCondition::none)
              {
                const ContactMap<dim> &contact = problem.contact;
                missed = contact.local_part(j, *residual) -
                         (1 - t) * balance_at_nodes[j][0] -
                         t * balance_at_nodes[j][1];
                contact.add_reaction(j, -missed, scratch);
              }
            const NodeAtStep at = node_at(j, t, missed);
            const double phi_n = at.r[0] - std::min(0., at.augmented_normal);
            Tensor<1, dim> z     = at.z;
            if (z.norm() > at.bound)
              z *= at.bound / z.norm();
            Tensor<1, dim> phi_t = at.r - z;
            phi_t[0]             = 0;
            // A node whose normal direction a support holds has c_j = 0
            // (no free normal component): the mean scale serves it.
            sum += (phi_n * phi_n + phi_t * phi_t) / (c[j] > 0 ? c[j] : mean_c);
          }
        const double balance =
          inside ? scratch.norm_sqr() :
                   balance_a + 2 * t * balance_b + t * t * balance_c;
        return Utilities::MPI::sum(sum, du_0.get_mpi_communicator()) +
               balance / mean_c;
      }

    private:
      /// A node's reaction, augmented normal reaction r_n + c_j g, friction
      /// bound and augmented tangential reaction z at a point of the step.
      struct NodeAtStep
      {
        Tensor<1, dim> r;
        double         augmented_normal;
        double         bound;
        Tensor<1, dim> z;
      };

      /// Node @p j at the point @p t, its reaction corrected by @p missed.
      NodeAtStep
      node_at(const unsigned int j, const double t, const Tensor<1, dim> &missed) const
      {
        const Tensor<1, dim> u_j =
          (1 - t) * problem.relative_displacement(j, du_0) +
          t * problem.relative_displacement(j, du_1);
        NodeAtStep at;
        at.r = (1 - t) * r_0[j] + t * r_1[j] + missed;
        if (!step_turns.empty())
          at.r += problem.contact.frame_turn(j, at.r, t * step_turns[j]);
        at.augmented_normal =
          at.r[0] + c[j] * (problem.gaps[j] - problem.approach(j, u_j));
        const double mu_j = friction ? problem.contact.friction_coefficient(j) : 0.;
        at.bound          = mu_j * std::max(0., -at.augmented_normal);
        at.z              = at.r - c_t[j] * u_j;
        at.z[0]           = 0;
        return at;
      }

      const IncrementalProblem<dim>     &problem;
      const std::vector<NodeCondition>  &conditions;
      const std::vector<double>         &c;
      const std::vector<double>         &c_t;
      const bool                         friction;
      const double                       mean_c;
      const Vector                      &du_0;
      const Vector                      &du_1;
      const std::vector<Tensor<1, dim>> &r_0;
      const std::vector<Tensor<1, dim>> &r_1;
      Vector                            &scratch;
      /// At each node in contact, its parts of the residuals at t = 0 and 1
      /// (nonlinear laws only).
      std::vector<std::array<Tensor<1, dim>, 2>> balance_at_nodes;
      double                             balance_a, balance_b, balance_c;
      const std::function<const Vector *(double)> nonlinear_residual;
      /// The turn of each frame per unit step (empty for fixed frames).
      std::vector<Tensor<1, dim>>         step_turns;
    };



    /// M followed by the projection onto the steps that keep the node
    /// conditions (NodeProjection::apply_to_step()), M the preconditioner
    /// of the Newton systems (a ConditionPreconditioner).
    template <int dim, typename Preconditioner>
    class ProjectedPreconditioner
    {
    public:
      ProjectedPreconditioner(const Preconditioner      &M,
                              const NodeProjection<dim> &P)
        : M(M)
        , P(P)
      {}

      void
      vmult(Vector &dst, const Vector &src) const
      {
        M.vmult(dst, src);
        P.apply_to_step(dst);
      }

    private:
      const Preconditioner      &M;
      const NodeProjection<dim> &P;
    };

    /**
     * A SolverControl that also gives up when the residual has not fallen
     * by a tenth below its best in 500 iterations (MeritWatch's rule): a
     * restarted GMRES on the Newton system of an iterate far from the
     * solution (3D ironing on 108 x 12 x 36 cells, a sliding increment)
     * stagnated at a few hundredths of its right-hand side and spent its
     * whole budget of 10,000 iterations there, minutes per cut increment.
     */
    class StagnationControl : public SolverControl
    {
    public:
      /// The iterations within which the residual must fall by a tenth.
      static constexpr unsigned int window = 500;

      StagnationControl(const unsigned int max_steps, const double tolerance)
        : SolverControl(max_steps, tolerance, false, false)
        , progress(window)
      {}

      State
      check(const unsigned int step, const double value) override
      {
        const State state = SolverControl::check(step, value);
        if (state == iterate && progress.stalled(step, value))
          {
            lcheck = failure;
            return failure;
          }
        return state;
      }

    private:
      MeritWatch progress;
    };

    /**
     * Solves A w = rhs to |rhs - A w| <= @p goal from w = 0: GMRES(50) when
     * a slipping node makes A non-symmetric, else CG; with a @p volumetric
     * split of K (a nearly incompressible body), GMRES on the mixed form
     * of A (volumetric_split.h), the preconditioner then being that of the
     * split's reduced stiffness. GMRES is flexible for a
     * @p variable_preconditioner (the geometric multigrid's V-cycle), and
     * restarted after @p flexible_restart iterations. FGMRES keeps two
     * vectors per iteration: with K matrix-free, the path for memory, 12,
     * since on example II at d = 1.6M (2 ranks) a restart after 25 took 22
     * Newton steps, 197 Krylov iterations, 82 s and a peak of 1,384 MB per
     * rank, after 12 19, 189, 81 s and 1,130 MB (GMRES(50) with the cycle:
     * 33, 365, 162 s); with K assembled, 30, where the vectors are a small
     * part of the memory: example II on one rank, Krylov iterations and
     * contact solve, restart 12 against 30: N_Y = 16 93 / 1.12 s against
     * 85 / 1.01 s, N_Y = 24 96 / 3.94 s against 89 / 3.60 s, N_Y = 28 145
     * / 9.6 s against 123 / 8.2 s (peak 465 against 478 MB), and on 2
     * ranks 120 / 4.28 s against 113 / 4.00 s (by hand; 50 as 30).
     * Returns the Krylov iterations; throws SolverControl::NoConvergence
     * (past @p max_iterations, or stagnating: StagnationControl), w then
     * the last iterate.
     */
    template <int dim, typename Preconditioner>
    unsigned int
    solve_newton_system(const ContactStiffness<dim> &A,
                        const Preconditioner        &preconditioner,
                        const VolumetricSplit       *volumetric,
                        const bool                   variable_preconditioner,
                        const bool                   non_symmetric,
                        const unsigned int           flexible_restart,
                        const unsigned int           max_iterations,
                        const double                 goal,
                        const Vector                &rhs,
                        Vector                      &w)
    {
      w = 0;
      if (volumetric != nullptr)
        {
          Vector     residual(rhs);
          const auto true_residual = [&](const Vector &x) {
            A.vmult(residual, x);
            residual -= rhs;
            return residual.l2_norm();
          };
          const auto finish = [&A](Vector &force, const Vector &u) {
            A.finish(force, u);
          };
          return MixedVolumetric::solve(*volumetric,
                                        finish,
                                        preconditioner,
                                        variable_preconditioner,
                                        true_residual,
                                        max_iterations,
                                        goal,
                                        w,
                                        rhs);
        }
      StagnationControl control(max_iterations, goal);
      if (non_symmetric)
        {
          if (variable_preconditioner)
            SolverFGMRES<Vector>(control,
                                 typename SolverFGMRES<Vector>::AdditionalData(
                                   flexible_restart))
              .solve(A, w, rhs, preconditioner);
          else
            SolverGMRES<Vector>(control,
                                typename SolverGMRES<Vector>::AdditionalData(50, true))
              .solve(A, w, rhs, preconditioner);
        }
      else
        {
          SolverCG<Vector> cg(control);
          cg.solve(A, w, rhs, preconditioner);
        }
      return control.last_step();
    }
  } // namespace SemismoothNewton
} // namespace FrictionalContact
