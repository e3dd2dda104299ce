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
   * linear operator with the conditions imposed by projection, and the
   * Krylov solve of the linear problem (the line search's merit:
   * semismooth_newton_merit.h).
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
                  // The gap's change along the step is zero.
                  removed    = Tensor<1, dim>();
                  removed[0] = part[0] - normal_closing_gap(gap_slopes[j], part, 0.);
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
        const double sigma = -r[j][0] - c[j] * problem.gap_at(j, u_j);
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
