#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <frictional_contact/driver/increment_drive.h>
#include <frictional_contact/driver/increment_response.h>
#include <frictional_contact/model/model.h>
#include <frictional_contact/model/mortar_basis.h>
#include <frictional_contact/model/mortar_preconditioner.h>
#include <frictional_contact/model/contact_results.h>
#include <frictional_contact/solvers/contact_problem.h>
#include <frictional_contact/solvers/contact_solver_parameters.h>
#include <frictional_contact/solvers/geometric_multigrid.h>
#include <frictional_contact/solvers/shifted_stiffness_solver.h>

#include <memory>
#include <vector>

namespace FrictionalContact
{
  /// The state of a run after its last finished increment.
  template <int dim>
  struct State
  {
    /// The total displacement u^l.
    TrilinosWrappers::MPI::Vector u;
    /// The contact force T_j r_j of each local candidate (Cartesian).
    std::vector<Tensor<1, dim>> contact_forces;
  };

  /// What solving one increment produced, converged or not.
  template <int dim>
  struct IncrementOutcome
  {
    /// The internal force of nonlinear laws over the increment (none for
    /// linear ones); on the heap, like the load, for the problem's pointer.
    std::unique_ptr<IncrementResponse<dim>> response;
    /// p = p^{l+1} - K (u^l + the prescribed increment); on the heap, so
    /// that the problem's reference to it survives a move of the outcome
    /// (the re-solves on adapted meshes assign outcomes).
    std::unique_ptr<TrilinosWrappers::MPI::Vector> load;
    /// The contact problem (none without contact).
    std::unique_ptr<IncrementalProblem<dim>> problem;
    /// The solution of the problem: du without the prescribed increment,
    /// and the reactions in the candidates' frames.
    TrilinosWrappers::MPI::Vector du_solved;
    std::vector<Tensor<1, dim>>   reactions;
    /// The whole displacement increment (constraints and prescribed
    /// displacements included); valid if the solve converged.
    TrilinosWrappers::MPI::Vector du;
    ContactResults<dim>           results;
    SolveStatistics               statistics;
    /// Solves of the increment for its contact pairs' geometry to settle
    /// (PairGeometry; 0 where the geometry is taken once), and the largest
    /// change of a slave normal the last one left.
    unsigned int geometry_passes = 0;
    double       geometry_change = 0;
  };

  /// Where a solve of an increment may start instead of from du = 0 and
  /// the last increment's contact forces: the displacement increment
  /// (without the prescribed one, in u) and the Cartesian contact forces
  /// of a solve of the same increment.
  template <int dim>
  struct WarmStart
  {
    TrilinosWrappers::MPI::Vector du;
    std::vector<Tensor<1, dim>>   forces;
    /// The solve's stopping tolerance where looser than the method's
    /// (IncrementalProblem::tolerance; 0: the method's).
    double tolerance = 0;
  };

  /**
   * Solves one increment on the model: the prescribed displacements, the
   * load, the elastic pre-solve, the contact problem and the chosen contact
   * solver. Owns the linear solver of K (and its AMG), the contact solver
   * and the spectral quantities Algorithm 2 needs (sigma_T, mu_pi, computed
   * once).
   */
  template <int dim>
  class IncrementSolver
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    IncrementSolver(ParameterHandler         &prm,
                    const ConditionalOStream &pcout);

    /// Builds the AMG of K and, with contact, sigma_T (again after the
    /// mesh changed; mu_pi is then computed anew when needed). With
    /// contact pairs the AMG is built at each increment, on its K_w.
    void
    initialize(const Model<dim> &model);

    /// Drops what refers to the current K or mesh, before the mesh changes.
    void
    release()
    {
      last_motion.clear();
      last_length = 0;
      last_drive  = IncrementDrive<dim>();
      linear_solver.release();
      mortar_cycle.reset();
      geometric.reset();
      geometric_with_springs.reset();
    }

    /// Prints the contact method and sigma_T.
    void
    print_method() const;

    /**
     * Solves increment number @p increment (counted from 1, for messages)
     * from @p t_start to @p t_end, the load factor going from
     * @p load_factor_start to @p load_factor, from @p state, the
     * obstacle already moved to its position at @p t_end, the contact
     * solve from @p warm_start if given. Throws a SolverError if the
     * elastic solve fails; a contact solve that does not converge is
     * reported in the outcome's statistics.
     */
    IncrementOutcome<dim>
    solve(Model<dim>             &model,
          const State<dim>       &state,
          const unsigned int      increment,
          const double            t_start,
          const double            t_end,
          const double            load_factor_start,
          const double            load_factor,
          const bool              record_history,
          TimerOutput            &timer,
          const WarmStart<dim>   *warm_start = nullptr);

    /// Whether the last solve() without a warm start started from the last
    /// increment's motion (<Contact solver/Start from the last increment>).
    bool
    started_from_last_increment() const
    {
      return started_from_last_motion;
    }

    /// Forgets the last increment's motion: the next solve starts from none
    /// (where starting from it did not converge: the motion turned).
    void
    forget_last_increment()
    {
      last_length = 0;
    }

    /// What the contact solver calls its iterations.
    std::string
    iteration_name() const
    {
      return solver.method->iteration_name();
    }

    /// The stiffness the solvers see: K, or with contact pairs K_w = Q^T K Q
    /// of the increment's mortar basis.
    const StiffnessOperator &
    stiffness(const Model<dim> &model) const
    {
      return mortar ? mortar->stiffness() : model.get_body().stiffness();
    }

    /// The solver of the linear systems with K, and its time counters.
    const ShiftedStiffnessSolver &
    get_linear_solver() const
    {
      return linear_solver;
    }

    /// What the last linear solve counted ("CG iterations (AMG)", ...).
    const std::string &
    last_linear_solve() const
    {
      return linear_solver.last_linear_solve;
    }

  private:
    /// Whether each increment tries the elastic solution first: when asked
    /// for and the method wants it.
    bool
    elastic_trial() const;

    /// mu_pi, computed when the contact iteration first needs it.
    double
    smallest_eigenvalue_of_K(const Model<dim> &model, TimerOutput &timer);

    /// The contact problem for the load @p outcome.load, from the
    /// displacement @p start (u^l and the prescribed increment).
    std::unique_ptr<IncrementalProblem<dim>>
    make_problem(const Model<dim>                    &model,
                 const TrilinosWrappers::MPI::Vector &load,
                 const TrilinosWrappers::MPI::Vector &start,
                 const Tensor<1, dim>                &obstacle_motion) const;

    /// The bodies of the model that only contact holds, for the problem:
    /// their names, which candidates hold them, and the stabilisation S.
    void
    describe_contact_held_bodies(const Model<dim>   &model,
                                 ContactHeldBodies &held) const;

    /// With contact pairs: the linear solver on K_w of this increment's
    /// basis (or its tangent), keeping the preconditioners of an earlier
    /// basis on this mesh unless @p rebuild asks for them anew on the
    /// tangent or the basis moved far from theirs
    /// (basis_change_in_preconditioner()); the geometric multigrid's
    /// cycle for K_w.
    void
    prepare_mortar_solves(const ElasticBody<dim> &body, bool rebuild);

    /// The factor by which the last increment's motion is taken as the
    /// start of an increment of length @p length driven by @p drive: the
    /// ratio of their lengths where the drive continues the last one's on
    /// the same mesh (<Start from the last increment>), else 0. Collective.
    double
    last_motion_scale(const IncrementDrive<dim> &drive, const double length) const
    {
      return drive.continues(last_drive, length, last_length) ? length / last_length : 0.;
    }

    /// Solves the contact problem of @p outcome from @p warm_start if
    /// given, else from the last increment's motion times @p motion_scale
    /// where that is positive (last_motion_scale()), else from no
    /// displacement; @p start is u^l with the prescribed increment.
    void
    solve_contact(const Model<dim>                    &model,
                  const State<dim>                    &state,
                  const TrilinosWrappers::MPI::Vector &start,
                  const double                         motion_scale,
                  IncrementOutcome<dim>               &outcome,
                  const bool                           record_history,
                  TimerOutput                         &timer,
                  const WarmStart<dim>                *warm_start);

    /**
     * What an increment needs before its solve, timed as "Increment start"
     * for every law: the pairs' basis, p - f_int(u_0) into the load of
     * @p outcome (a nonlinear law's IncrementResponse: its force and
     * tangent at @p start, linearised along @p lifting), the
     * preconditioner built again on the tangent where due, and the pairs'
     * solves. Collective.
     */
    void
    start_increment(Model<dim>                          &model,
                    const TrilinosWrappers::MPI::Vector &start,
                    const TrilinosWrappers::MPI::Vector &lifting,
                    const double                         load_factor,
                    IncrementOutcome<dim>               &outcome,
                    TimerOutput                         &timer);

    /// The geometric multigrid of K on the mesh's levels (for
    /// <Linear solver/Preconditioner> = geometric multigrid), given to the
    /// linear solver.
    void
    make_geometric_multigrid(const Model<dim> &model);

    /// The linear solver and its preconditioners on the body's K as it
    /// is now (without contact pairs: with them, each basis's K_w).
    void
    initialize_on_body(const ElasticBody<dim> &body);

    /**
     * For a nonlinear law: takes the baseline of Krylov iterations per
     * Newton step from the first solve after the preconditioner was built,
     * and asks for a build on the tangent before the next solve once
     * @p result took more than <Linear solver/Tangent rebuild factor>
     * times it.
     */
    void
    note_krylov_growth(const SolveStatistics &result);

    /**
     * How far the pairs' K_w has moved from the one the preconditioner was
     * built on, in the preconditioner's own measure: |M (K_w - K_w,old)
     * x| / |x| for a fixed field x. A slave much stiffer than its master
     * moves K_w far, in the master's scale, as the mortar rows change
     * (the slave's energy reaches the master's unknowns through them):
     * above largest_basis_change the AMG is built again. Collective.
     */
    double
    basis_change_in_preconditioner(const ElasticBody<dim> &body) const;

    /// The basis change above which the pairs' AMG is built again: of the
    /// block on block dragged with equal moduli at most 0.05 was measured
    /// per increment, of a slave 1e3 times stiffer 0.33 to 48 and their
    /// Krylov iterations doubled to tripled with the old AMG.
    static constexpr double largest_basis_change = 0.25;

    /// Results per candidate for the solution in @p outcome.
    ContactResults<dim>
    contact_results(const ContactOperator<dim>  &contact,
                    const State<dim>            &state,
                    const IncrementOutcome<dim> &outcome) const;

    const ConditionalOStream    &pcout;
    ShiftedStiffnessSolver       linear_solver;
    ContactSolverParameters<dim> solver;
    /// The basis u = Q w of the increment's contact pairs (none without),
    /// and the one whose K_w the preconditioners were built from: they are
    /// kept from increment to increment while the mesh stays.
    std::shared_ptr<MortarBasis<dim>> mortar;
    std::shared_ptr<MortarBasis<dim>> preconditioner_basis;
    /// The matrix that preconditioner was built on (K_w of that basis, or
    /// tangent_copy).
    const StiffnessOperator *preconditioner_matrix = nullptr;
    /// The geometric multigrid of K, and a second one for the springs of
    /// the Newton systems (both on the mesh's levels, matrix-free).
    std::unique_ptr<GeometricMultigrid<dim>> geometric;
    std::unique_ptr<GeometricMultigrid<dim>> geometric_with_springs;
    /// With contact pairs, the first for K_w of the increment's basis.
    std::unique_ptr<MortarPreconditioner<dim>> mortar_cycle;
    /// The copy of the tangent K_T,w a rebuild for it took (contact
    /// pairs, whose basis makes K_T,w anew at each Newton step).
    TrilinosWrappers::SparseMatrix       tangent_copy;
    std::unique_ptr<StiffnessOperator>   tangent_copy_operator;
    /// Krylov iterations per Newton step of the first solve after the
    /// preconditioner was built (0: not yet), and whether the next solve
    /// builds it again on the tangent (note_krylov_growth()).
    double krylov_per_step_after_build = 0;
    bool   rebuild_for_tangent         = false;
    /// The displacement increment of the last increment solved on this
    /// mesh, without its prescribed part, its length in time and what
    /// drove it (empty unless <Start from the last increment>; a converged
    /// solve the driver then rejected, such as a pass of the pairs'
    /// geometry, counts too: it is only where the next solve starts).
    TrilinosWrappers::MPI::Vector last_motion;
    double                        last_length = 0;
    IncrementDrive<dim>           last_drive;
    /// See started_from_last_increment().
    bool                          started_from_last_motion = false;
    double                       sigma_T = 1;
    double                       mu_pi   = 0;
    bool                         contact_active = false;
  };
} // namespace FrictionalContact
