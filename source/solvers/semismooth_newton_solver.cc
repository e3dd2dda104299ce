#include <deal.II/base/timer.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/solver_control.h>

#include <frictional_contact/base/plugins.h>
#include <frictional_contact/solvers/semismooth_newton_solver.h>

#include <sstream>

namespace FrictionalContact
{
  namespace
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
     * The orthogonal projection onto displacements that leave the fixed
     * directions of the node conditions alone: removes the normal part at
     * slipping nodes and the whole nodal vector at sticking ones.
     */
    template <int dim>
    class NodeProjection
    {
    public:
      NodeProjection(const ContactMap<dim>             &contact,
                     const std::vector<NodeCondition> &conditions)
        : contact(contact)
        , conditions(conditions)
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

    private:
      const ContactMap<dim>             &contact;
      const std::vector<NodeCondition> &conditions;
    };

    /**
     * The Newton operator on the subspace of the node conditions:
     * w -> P ((I + C) K w + B w). C couples the friction force of a
     * slipping node to its normal reaction, so that its tangential equation
     * reads T_t^T R + mu n (t_n^T R) + kappa Q T_t^T du = 0 with R = K du - p:
     * r_t = -mu r_n n - kappa Q u_t, the linearisation of
     * r_t = mu |r_n| zeta / |zeta| (Q = I - n n^T, the tangential directions
     * across the slip; B is this Robin term, zero in 2D). Without slipping
     * nodes the operator is P K P, symmetric.
     */
    template <int dim>
    class ContactStiffness
    {
    public:
      ContactStiffness(const TrilinosWrappers::SparseMatrix &K,
                       const NodeProjection<dim>            &P,
                       const ContactMap<dim>                 &contact,
                       const std::vector<NodeCondition>     &conditions,
                       const std::vector<Tensor<1, dim>>    &slip_direction,
                       const std::vector<double>            &robin,
                       const double                          mu)
        : K(K)
        , P(P)
        , contact(contact)
        , conditions(conditions)
        , slip_direction(slip_direction)
        , robin(robin)
        , mu(mu)
      {}

      void
      vmult(Vector &dst, const Vector &src) const
      {
        K.vmult(dst, src);
        couple(dst);
        add_robin(src, 1., dst);
        P.apply(dst);
      }

      /// v += C v: the friction force that goes with the normal reaction.
      void
      couple(Vector &v) const
      {
        if (mu == 0)
          return;
        for (unsigned int j = 0; j < contact.n_local(); ++j)
          if (conditions[j] == NodeCondition::normal_fixed)
            {
              const double r_n = contact.local_part(j, v)[0];
              contact.add_reaction(j, mu * r_n * slip_direction[j], v);
            }
      }

      /// dst += factor B u.
      void
      add_robin(const Vector &u, const double factor, Vector &dst) const
      {
        if (mu == 0 || dim == 2)
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
      const TrilinosWrappers::SparseMatrix &K;
      const NodeProjection<dim>            &P;
      const ContactMap<dim>                 &contact;
      const std::vector<NodeCondition>     &conditions;
      const std::vector<Tensor<1, dim>>    &slip_direction;
      const std::vector<double>            &robin;
      const double                          mu;
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
        , flips(c_t.size(), 0)
      {}

      std::vector<NodeCondition>  conditions;
      /// mu max(sigma_j, 0): the friction bound of each node.
      std::vector<double>         bound;
      std::vector<Tensor<1, dim>> slip_direction;
      /// kappa_j of the Robin term across the slip (3D).
      std::vector<double>         robin;
      /// c_t per node, and how often its stick/slip state went back and
      /// forth.
      std::vector<double>       c_t;
      std::vector<unsigned int> flips;
    };

    /**
     * Sorts the nodes by the augmented reactions of (du, r): free where the
     * augmented normal reaction sigma_j is not positive, stick inside the
     * friction bound, slip on it. Returns whether a node of this rank
     * changed its condition.
     */
    template <int dim>
    bool
    classify(const IncrementalProblem<dim>     &problem,
             const Vector                      &du,
             const std::vector<Tensor<1, dim>> &r,
             const std::vector<double>         &c,
             const double                       mu_k,
             ActiveSets<dim>                   &sets)
    {
      const unsigned int n       = c.size();
      bool               changed = false;
    for (unsigned int j = 0; j < n; ++j)
      {
        const Tensor<1, dim> u_j = problem.relative_displacement(j, du);
        const double sigma = -r[j][0] - c[j] * (problem.gaps[j] - u_j[0]);
        Tensor<1, dim> zeta = r[j] - sets.c_t[j] * u_j;
        zeta[0]             = 0;
        const double zeta_norm = zeta.norm();
        const NodeCondition before = sets.conditions[j];
        const Tensor<1, dim> direction_before = sets.slip_direction[j];
        sets.bound[j] = mu_k * std::max(sigma, 0.);
        if (!(sigma > 0))
          sets.conditions[j] = NodeCondition::none;
        else if (mu_k > 0 && zeta_norm < sets.bound[j])
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
        changed = changed || sets.conditions[j] != before;
        // Anti-cycling: stick <-> slip, or a reversed slip direction.
        const bool flipped =
          before != NodeCondition::none &&
          sets.conditions[j] != NodeCondition::none &&
          (sets.conditions[j] != before ||
           (before == NodeCondition::normal_fixed &&
            sets.slip_direction[j] * direction_before < 0));
        if (mu_k > 0 && flipped && ++sets.flips[j] >= 2)
          {
            sets.c_t[j] *= 0.1;
            sets.flips[j] = 0;
          }
      }
      return changed;
    }



    /**
     * The merit of the line search at the point t of the segment from the
     * previous iterate (du_0, r_0) to the new one (du_1, r_1): the squared
     * complementarity functions of all nodes, scaled by c_j, plus the
     * squared force balance residual (linear along the segment), scaled by
     * the mean c. Collective.
     */
    template <int dim>
    class MeritAlongStep
    {
    public:
      MeritAlongStep(const IncrementalProblem<dim>     &problem,
                     const std::vector<double>         &c,
                     const std::vector<double>         &c_t,
                     const double                       mu_k,
                     const double                       mean_c,
                     const Vector                      &du_0,
                     const Vector                      &du_1,
                     const std::vector<Tensor<1, dim>> &r_0,
                     const std::vector<Tensor<1, dim>> &r_1,
                     const Vector                      &balance_0,
                     const Vector                      &balance_1,
                     Vector                            &scratch)
        : problem(problem)
        , c(c)
        , c_t(c_t)
        , mu_k(mu_k)
        , mean_c(mean_c)
        , du_0(du_0)
        , du_1(du_1)
        , r_0(r_0)
        , r_1(r_1)
      {
        balance_a = balance_0.norm_sqr();
        balance_b = balance_0 * balance_1 - balance_a;
        scratch   = balance_1;
        scratch -= balance_0;
        balance_c = scratch.norm_sqr();
      }

      double
      operator()(const double t) const
      {
        double sum = 0;
        for (unsigned int j = 0; j < c.size(); ++j)
          {
            const Tensor<1, dim> u_j =
              (1 - t) * problem.relative_displacement(j, du_0) +
              t * problem.relative_displacement(j, du_1);
            const Tensor<1, dim> r_j   = (1 - t) * r_0[j] + t * r_1[j];
            const double         gap   = problem.gaps[j] - u_j[0];
            const double         phi_n = r_j[0] - std::min(0., r_j[0] + c[j] * gap);
            const double bound_j = mu_k * std::max(0., -(r_j[0] + c[j] * gap));
            Tensor<1, dim> z     = r_j - c_t[j] * u_j;
            z[0]                 = 0;
            if (z.norm() > bound_j)
              z *= bound_j / z.norm();
            Tensor<1, dim> phi_t = r_j - z;
            phi_t[0]             = 0;
            sum += (phi_n * phi_n + phi_t * phi_t) / c[j];
          }
        return Utilities::MPI::sum(sum, du_0.get_mpi_communicator()) +
               (balance_a + 2 * t * balance_b + t * t * balance_c) / mean_c;
      }

    private:
      const IncrementalProblem<dim>     &problem;
      const std::vector<double>         &c;
      const std::vector<double>         &c_t;
      const double                       mu_k;
      const double                       mean_c;
      const Vector                      &du_0;
      const Vector                      &du_1;
      const std::vector<Tensor<1, dim>> &r_0;
      const std::vector<Tensor<1, dim>> &r_1;
      double                             balance_a, balance_b, balance_c;
    };



    /// P M P with M the preconditioner of K (the AMG, unless <Linear
    /// solver/Preconditioner> asks for Jacobi).
    template <int dim>
    class ProjectedPreconditioner
    {
    public:
      ProjectedPreconditioner(const ShiftedStiffnessSolver &stiffness_solver,
                              const NodeProjection<dim>    &P)
        : stiffness_solver(stiffness_solver)
        , P(P)
      {}

      void
      vmult(Vector &dst, const Vector &src) const
      {
        stiffness_solver.precondition_stiffness(dst, src);
        P.apply(dst);
      }

    private:
      const ShiftedStiffnessSolver &stiffness_solver;
      const NodeProjection<dim>    &P;
    };
    /**
     * Solves A w = rhs to |rhs - A w| <= @p goal from w = 0: GMRES(50) when
     * a slipping node makes A non-symmetric, else CG. Returns the Krylov
     * iterations; throws SolverControl::NoConvergence.
     */
    template <int dim>
    unsigned int
    solve_newton_system(const ContactStiffness<dim>        &A,
                        const ProjectedPreconditioner<dim> &preconditioner,
                        const bool                          non_symmetric,
                        const unsigned int                  max_iterations,
                        const double                        goal,
                        const Vector                       &rhs,
                        Vector                             &w)
    {
      SolverControl control(max_iterations, goal, false, false);
      w = 0;
      if (non_symmetric)
        {
          SolverGMRES<Vector> gmres(
            control, typename SolverGMRES<Vector>::AdditionalData(50, true));
          gmres.solve(A, w, rhs, preconditioner);
        }
      else
        {
          SolverCG<Vector> cg(control);
          cg.solve(A, w, rhs, preconditioner);
        }
      return control.last_step();
    }
  } // namespace



  template <int dim>
  void
  SemismoothNewtonSolver<dim>::declare_parameters(ParameterHandler &prm)
  {
    StoppingRule::declare_parameters(
      prm,
      "1e-10",
      "Stop when the paper's three residuals, with the reactions projected "
      "onto the friction cones, are small: force balance below this times "
      "|p|, penetration below this times the length scale L (the largest gap "
      "or displacement), complementarity below this times |p| L. Each term "
      "of the complementarity sum is non-negative for reactions in the cone, "
      "so the sum measures every node. For an FCLIB problem (--fclib): stop "
      "when FCLIB's error measure is below this.",
      "100",
      "Newton iterations allowed per increment.");
    prm.declare_entry("Tangential parameter",
                      "0.1",
                      Patterns::Double(0.),
                      "c_t,j = this times c_j in zeta = r_t - c_t u_t. A node "
                      "whose stick/slip state keeps changing gets a c_t ten "
                      "times smaller: a large c_t makes the slip direction "
                      "flip back and forth, a small one decides by the force.");
    prm.declare_entry("Linear reduction",
                      "1e-2",
                      Patterns::Double(0., 1.),
                      "CG (or GMRES) reduces the residual of each Newton step "
                      "by this factor, ten times more after a step the line "
                      "search had to shorten.");
  }



  template <int dim>
  void
  SemismoothNewtonSolver<dim>::parse_parameters(ParameterHandler &prm)
  {
    this->stop.parse_parameters(prm, "Semismooth Newton");
    linear_reduction = prm.get_double("Linear reduction");
    tangential_factor = prm.get_double("Tangential parameter");
  }



  template <int dim>
  std::string
  SemismoothNewtonSolver<dim>::describe() const
  {
    return "semismooth Newton (primal-dual active set), tolerance " +
           Input::to_text(this->stop.tolerance);
  }



  template <int dim>
  SolveStatistics
  SemismoothNewtonSolver<dim>::solve(const IncrementalProblem<dim> &problem,
                                     ShiftedStiffnessSolver &linear_solver,
                                     Vector                 &du,
                                     std::vector<Tensor<1, dim>> &r,
                                     const bool record_history) const
  {
    const Timer                           timer;
    const ContactMap<dim>                &contact = problem.contact;
    const TrilinosWrappers::SparseMatrix &K       = problem.stiffness;
    const double       mu       = contact.friction_coefficient();
    const unsigned int n        = contact.n_local();
    const MPI_Comm     comm     = du.get_mpi_communicator();
    const unsigned int setups   = linear_solver.n_amg_setups;
    linear_solver.prepare_stiffness_preconditioner();

    const std::vector<double> c = contact.normal_stiffness(K);

    std::vector<double> initial_c_t(n);
    for (unsigned int j = 0; j < n; ++j)
      initial_c_t[j] = tangential_factor * c[j];
    ActiveSets<dim>                   sets(initial_c_t);
    const std::vector<NodeCondition> &conditions     = sets.conditions;
    const std::vector<Tensor<1, dim>> &slip_direction = sets.slip_direction;
    const std::vector<double>         &robin          = sets.robin;
    const std::vector<double>         &c_t            = sets.c_t;

    // From a cold start, the frictionless problem first: the normal sets
    // settle in a few steps, and friction then starts from real pressures.
    double r_norm = 0;
    for (unsigned int j = 0; j < n; ++j)
      r_norm = std::max(r_norm, r[j].norm());
    bool friction = mu > 0 && Utilities::MPI::max(r_norm, comm) > 0;

    const double load_norm = problem.load.l2_norm();

    Vector K_du(du), rhs(du), w(du), T_r(du), scratch(du), previous_du(du);
    // The force balance residual K du - p - T r of the previous iterate.
    Vector                      previous_residual(du), residual(du);
    std::vector<Tensor<1, dim>> previous_r(n), admissible_r(n);
    double                      mean_c = 0;
    for (unsigned int j = 0; j < n; ++j)
      mean_c += c[j];
    mean_c = Utilities::MPI::sum(mean_c, comm) /
             std::max<double>(1, contact.n_candidates());
    K.vmult(K_du, du);
    contact.apply(r, T_r);
    SolveStatistics           result;
    const NodeProjection<dim> P(contact, conditions);
    bool                      first         = true;
    double                    best_merit    = std::numeric_limits<double>::max();
    double                    reduction     = linear_reduction;
    unsigned int              last_progress = 0;

    for (unsigned int k = 0; k < this->stop.max_iterations; ++k)
      {
        // Done when the residuals of the current iterate are small.
        if (!first)
          {
            const double length =
              std::max(problem.length_scale, du.linfty_norm());
            const Residuals &res = result.residuals;
            if (res.force_balance <= this->stop.tolerance * load_norm &&
                res.penetration <= this->stop.tolerance * length &&
                res.complementarity <= this->stop.tolerance * load_norm * length)
              {
                result.converged = true;
                break;
              }
          }
        first = false;

        // Sort the nodes by the augmented reactions of the current iterate.
        const double mu_k    = friction ? mu : 0.;
        const bool   changed = Utilities::MPI::logical_or(
          classify(problem, du, r, c, mu_k, sets), comm);
        if (!friction && mu > 0 && !changed && k > 0)
          {
            friction      = true; // the normal sets have settled
            first         = true;
            best_merit    = std::numeric_limits<double>::max();
            last_progress = k;
            --k;
            continue;
          }

        // The linear problem: du = du_D + w, with du_D meeting the node
        // conditions and w in the subspace where they are homogeneous.
        previous_du   = du;
        previous_r    = r;
        previous_residual = K_du;
        previous_residual -= problem.load;
        previous_residual -= T_r;
        rhs           = problem.load;
        bool any_slip = false;
        for (unsigned int j = 0; j < n; ++j)
          {
            if (conditions[j] == NodeCondition::none)
              continue;
            const Tensor<1, dim> current = contact.local_part(j, du);
            Tensor<1, dim>       target  = current;
            target[0]                    = problem.gaps[j];
            if (conditions[j] == NodeCondition::all_fixed)
              for (unsigned int d = 1; d < dim; ++d)
                target[d] = problem.obstacle_slip[j][d];
            contact.add_reaction(j, target - current, du);
            if (conditions[j] == NodeCondition::normal_fixed)
              any_slip = true;
          }
        any_slip = Utilities::MPI::logical_or(any_slip && mu_k > 0, comm);
        const ContactStiffness<dim> A(K,
                                      P,
                                      contact,
                                      conditions,
                                      slip_direction,
                                      robin,
                                      any_slip ? mu_k : 0.);
        K.vmult(K_du, du);
        rhs -= K_du;
        if (any_slip)
          {
            A.couple(rhs);
            // - B (du_D - the obstacle's slip)
            A.add_robin(du, -1., rhs);
            for (unsigned int j = 0; j < n; ++j)
              if (conditions[j] == NodeCondition::normal_fixed)
                {
                  Tensor<1, dim> slip = problem.obstacle_slip[j];
                  slip -= (slip * slip_direction[j]) * slip_direction[j];
                  if (dim == 3)
                    contact.add_reaction(j, robin[j] * slip, rhs);
                }
          }
        P.apply(rhs);

        w                    = 0;
        const double initial = rhs.l2_norm();
        const double goal =
          std::max(reduction * initial, 0.1 * this->stop.tolerance * load_norm);
        unsigned int linear_iterations = 0;
        try
          {
            linear_iterations = solve_newton_system(
              A, ProjectedPreconditioner<dim>(linear_solver, P), any_slip,
              linear_solver.maximum_iterations(), goal, rhs, w);
          }
        catch (const SolverControl::NoConvergence &e)
          {
            result.failure =
              "the linear solve of Newton iteration " + std::to_string(k + 1) +
              " did not converge (residual " + Input::scientific(e.last_residual) +
              " after " + std::to_string(e.last_step) + " iterations, goal " +
              Input::scientific(goal) +
              "); raise <Linear solver/Maximum iterations>";
            break;
          }
        result.linear_iterations += linear_iterations;
        du += w;

        // Reactions: the residual K du - p at the active nodes. (They may
        // leave the cones on the way; the residuals below judge their
        // projection onto the cones.)
        K.vmult(K_du, du);
        scratch = K_du;
        scratch -= problem.load;
        for (unsigned int j = 0; j < n; ++j)
          {
            r[j] = Tensor<1, dim>();
            if (conditions[j] == NodeCondition::none)
              continue;
            r[j] = contact.local_part(j, scratch);
          }

        // Line search along the segment from the previous iterate, on the
        // complementarity functions and the force balance: a full step can
        // make the stick/slip sets cycle, a shorter one cannot increase
        // this merit. The force balance is linear along the segment.
        contact.apply(r, T_r);
        residual = K_du;
        residual -= problem.load;
        residual -= T_r;
        const MeritAlongStep<dim> merit(problem, c, c_t, mu_k, mean_c,
                                        previous_du, du, previous_r, r,
                                        previous_residual, residual, scratch);
        const double merit_before = merit(0.);
        double       t            = 1;
        while (t > 1. / 64 && merit(t) > (1 - 1e-4 * t) * merit_before)
          t /= 2;
        // A damped step says the direction was poor: solve the next one
        // more accurately; full steps relax the accuracy again.
        reduction = t < 1 ? std::max(0.1 * reduction, 1e-8) :
                            std::min(10 * reduction, linear_reduction);

        // No progress: the merit has not dropped by a tenth in 25 steps.
        const double merit_after = merit(t);
        if (merit_after < 0.9 * best_merit)
          {
            best_merit    = merit_after;
            last_progress = k;
          }
        if (k > last_progress + 25)
          {
            result.failure = "no progress from Newton iteration " +
                             std::to_string(last_progress + 1) + " to " +
                             std::to_string(k + 1) +
                             " (the stick/slip sets keep changing); try "
                             "smaller increments, Loading/On failure = cut "
                             "increment, or Method = accelerated primal-dual";
            break;
          }
        if (t < 1)
          {
            du.sadd(t, 1 - t, previous_du);
            for (unsigned int j = 0; j < n; ++j)
              r[j] = (1 - t) * previous_r[j] + t * r[j];
            K.vmult(K_du, du);
          }
        contact.apply(r, T_r);

        previous_du -= du;
        result.iterations = k + 1;
        result.last_step  = previous_du.l2_norm();
        for (unsigned int j = 0; j < n; ++j)
          admissible_r[j] = contact.friction_cone().project(r[j]);
        contact.apply(admissible_r, scratch);
        result.residuals =
          compute_residuals(problem, du, K_du, scratch, admissible_r, w);
        const HistoryRow row{k + 1,
                             timer.wall_time(),
                             result.residuals,
                             result.last_step,
                             linear_iterations};
        if (record_history)
          result.history.push_back(row);
        this->report(k + 1, row);
        if (!result.residuals.finite())
          {
            result.failure = "NaN or infinity at Newton iteration " +
                             std::to_string(k + 1);
            break;
          }
      }
    r = admissible_r;
    if (!result.converged && result.failure.empty())
      result.failure = "no convergence in " + std::to_string(this->stop.max_iterations) +
                       " Newton iterations; raise <Contact solver/Semismooth "
                       "Newton/Maximum iterations> or use smaller increments";
    result.amg_setups = linear_solver.n_amg_setups - setups;
    result.seconds    = timer.wall_time();
    return result;
  }

  FRICTIONAL_CONTACT_REGISTER_PLUGIN(
    ContactSolver,
    SemismoothNewtonSolver,
    "semismooth Newton",
    "A primal-dual active set (semismooth Newton) method: per iteration "
    "one linear elastic solve with the contact conditions imposed by "
    "projection, the friction force coupled to the normal reaction at "
    "slipping nodes, CG or GMRES preconditioned by the AMG of K, and a line "
    "search.")
} // namespace FrictionalContact
