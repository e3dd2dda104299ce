#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <frictional_contact/solvers/stiffness_operator.h>
#include <frictional_contact/solvers/shifted_cholesky.h>
#include <frictional_contact/solvers/spring_amg.h>
#include <frictional_contact/solvers/volumetric_split.h>

#include <memory>
#include <string>
#include <vector>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * Solves (K + sigma I) x = b with preconditioned conjugate gradients,
   * warm-started from the x it is given. Kanno's primal step
   * (beta K + I) x = b is this system with sigma = 1/beta; sigma = 0 is the
   * plain elastic problem. Owns the preconditioner and decides, from sigma,
   * which one to use and when to rebuild it:
   *
   * - Jacobi (diagonal of K + sigma I) when the identity is strong
   *   enough, max diag(K) <= "Jacobi threshold" * sigma: CG's iterations
   *   then depend on that ratio, not on the mesh, and each costs one
   *   product with K (the paper's examples have ratios 2 to 20);
   * - else, for sigma > 0 on one process, a sparse Cholesky factorization
   *   of K + sigma_ref I (ShiftedCholesky) if its factor is not much
   *   denser than K, refactored when sigma leaves a factor "Cholesky
   *   refactorization factor" of sigma_ref;
   * - otherwise Trilinos ML (smoothed aggregation, or plain aggregation
   *   with "AMG prolongator damping" = 0, with the rigid-body modes as near
   *   null space) built on K + sigma_ref I, reused while sigma stays
   *   within a factor "AMG rebuild factor" of sigma_ref (or both are below
   *   the stiffness scale, where the shift does not matter). The AMG of the
   *   plain elastic problem (sigma = 0) is kept separately, and so is its
   *   variant with springs for the Newton systems (spring_preconditioner()).
   */
  class ShiftedStiffnessSolver
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    static void
    declare_parameters(ParameterHandler &prm);

    /// Reads the subsection "Linear solver"; @p dim is the number of
    /// displacement components per node (ML's block size).
    ShiftedStiffnessSolver(ParameterHandler &prm, const unsigned int dim);

    /**
     * Keeps a reference to @p stiffness (which must outlive this object)
     * and the near null space for the AMG (one vector per rigid-body mode,
     * each of the locally owned size, the dim translations first; or the
     * translations alone where no coordinates are known). With a @p volumetric split (a
     * nearly incompressible body; its matrices must outlive this object
     * too), the AMG is built on its reduced stiffness A and the solves
     * with AMG go through the mixed system (volumetric_split.h).
     */
    void
    initialize(const StiffnessOperator          &stiffness,
               std::vector<std::vector<double>>  rigid_body_modes,
               const double                      smallest_eigenvalue_estimate = 0,
               const VolumetricSplit            &volumetric = {});

    /// The volumetric split of K, or nullptr if K has none.
    const VolumetricSplit *
    volumetric_split() const
    {
      return split.reduced_stiffness != nullptr ? &split : nullptr;
    }

    /// Whether the solves go through a volumetric split where K has one
    /// (<Nearly incompressible solves> = mixed).
    bool
    solves_mixed() const
    {
      return mixed_solves;
    }

    /**
     * Solves with @p stiffness (and @p volumetric) from now on, but keeps
     * the preconditioners, built on the matrix initialize() was given
     * (which must then outlive them): for a K that changes a little, such
     * as the Q^T K Q of contact pairs from one increment to the next.
     */
    void
    replace_matrix(const StiffnessOperator &stiffness,
                   const VolumetricSplit   &volumetric = {});

    /**
     * The geometric multigrid V-cycles (GeometricMultigrid, which knows the
     * mesh this class does not) used when <Preconditioner> = geometric
     * multigrid: @p of_stiffness for the elastic solves, @p with_springs
     * for the Newton systems (spring_preconditioner()). They must outlive
     * their use; give nullptr to drop them.
     */
    void
    set_geometric_multigrid(const SpringPreconditioner *of_stiffness,
                            SpringPreconditioner       *with_springs);

    /// <Tangent rebuild factor> (0: never).
    double
    tangent_rebuild_factor() const
    {
      return tangent_rebuild;
    }

    /// Whether <Preconditioner> asks for geometric multigrid.
    bool
    wants_geometric_multigrid() const
    {
      return preconditioner_choice == "geometric multigrid";
    }

    /// <Multigrid smoother degree>.
    unsigned int
    multigrid_smoother_degree() const
    {
      return multigrid_degree;
    }

    /// Drops the preconditioners and the reference to K, before K changes
    /// (a new mesh); initialize() again before the next solve.
    void
    release();

    /**
     * Solves (K + sigma I) x = b until |b - (K + sigma I) x| <= tolerance,
     * starting from @p x. Returns the number of CG iterations. Throws a
     * SolverError if CG does not converge.
     */
    unsigned int
    solve(const double sigma,
          Vector      &x,
          const Vector &b,
          const double tolerance);

    /// Makes the preconditioner of K itself that <Linear solver/
    /// Preconditioner> chooses (the AMG is built on first use, then kept),
    /// for precondition_stiffness().
    void
    prepare_stiffness_preconditioner();

    /// dst = M^-1 src with the preconditioner of K made by
    /// prepare_stiffness_preconditioner().
    void
    precondition_stiffness(Vector &dst, const Vector &src) const;

    /// Krylov iterations allowed per linear solve.
    unsigned int
    maximum_iterations() const
    {
      return max_iterations;
    }

    /// The relative tolerance of elastic solves.
    double
    relative_tolerance() const
    {
      return rel_tolerance;
    }

    /// Whether the preconditioner of the elastic solves and the Newton
    /// systems is not a fixed linear map: the geometric multigrid's V-cycle
    /// (single precision, a coarse CG to 1e-3), for which GMRES must be
    /// flexible.
    bool
    preconditioner_varies() const
    {
      return use_geometric_multigrid(0.);
    }

    /// Whether spring_preconditioner() is the geometric multigrid.
    bool
    newton_uses_geometric_multigrid() const
    {
      return use_geometric_multigrid(0.) && geometric_with_springs != nullptr;
    }

    /**
     * The preconditioner of K plus springs: the geometric multigrid's
     * with springs if one was given, else the AMG (SpringAMG) taken from
     * the AMG of K (built first if needed) and kept until release(); not
     * initialized() when <Linear solver/Preconditioner> makes K's
     * preconditioner Jacobi or the AMG smoother is not Chebyshev (its fine
     * level smooths as ML's Chebyshev does).
     */
    SpringPreconditioner &
    spring_preconditioner();

    /// Seconds of AMG set-ups: ML's of K and the Newton preconditioner's
    /// (taken from it, and made again for each new set of springs).
    double
    amg_setup_wall_time() const
    {
      return amg_setup_seconds + spring_amg.setup_seconds;
    }

    /// How many times the AMG was set up, and the seconds ML's set-ups took.
    unsigned int n_amg_setups = 0;
    double       amg_setup_seconds = 0;
    /// Seconds of the set-ups of the geometric multigrid (counted by
    /// whoever makes it).
    double multigrid_setup_seconds = 0;
    /// How many numeric Cholesky factorizations were made, and their
    /// seconds (the ordering included).
    unsigned int n_factorizations = 0;
    double       factorization_seconds = 0;
    /// Wall seconds in Krylov solves with K (the preconditioner's
    /// applications included, its set-ups not): the elastic solves, the
    /// primal steps and the Newton systems.
    double krylov_seconds = 0;

    /// What the last solve counted: "CG iterations (AMG)", "CG iterations
    /// (Jacobi)" or, through the mixed system, "GMRES iterations (AMG,
    /// mixed form)".
    std::string last_linear_solve;

  private:
    /// Whether the solve with @p sigma takes the geometric V-cycle.
    bool
    use_geometric_multigrid(const double sigma) const;

    bool
    use_jacobi(const double sigma) const;

    /// Whether the primal step with @p sigma is preconditioned by the
    /// Cholesky factorization (analyzing K on first use, to see whether
    /// its factor is sparse enough).
    bool
    use_cholesky(const double sigma);

    /// The factorization for @p sigma, refactored if needed.
    const ShiftedCholesky &
    cholesky_for(const double sigma);

    /// How many of the rigid-body modes make the AMG's near null space:
    /// all, or the dim translations (<AMG near null space>).
    unsigned int
    n_null_space_modes() const;

    /// An AMG hierarchy and the matrix K + sigma I it was built on.
    struct AMG
    {
      TrilinosWrappers::PreconditionAMG preconditioner;
      TrilinosWrappers::SparseMatrix    matrix;
      double                            sigma = -1;
    };

    /// The AMG for @p sigma, (re)built if needed: of K + sigma I, or of
    /// A + sigma I with a volumetric split.
    const TrilinosWrappers::PreconditionAMG &
    amg_for(const double sigma);

    /// The matrix the AMG is built from: K, or A with a volumetric split
    /// (those initialize() was given).
    const TrilinosWrappers::SparseMatrix &
    amg_matrix() const
    {
      return preconditioner_split.reduced_stiffness != nullptr ?
               *preconditioner_split.reduced_stiffness :
               preconditioner_stiffness->matrix("the AMG (Trilinos ML)");
    }

    void
    build_jacobi(const double sigma);

    /// Displacement components per node.
    const unsigned int dim;

    // Parameters.
    double       rel_tolerance;
    unsigned int max_iterations;
    std::string  preconditioner_choice;
    double       jacobi_threshold;
    unsigned int multigrid_degree;
    double       rebuild_factor;
    double       tangent_rebuild;
    double       refactorization_factor;
    unsigned int smoother_sweeps;
    std::string  smoother_type;
    std::string  coarse_solver;
    double       aggregation_threshold;
    double       prolongator_damping;
    bool         translations_only;
    /// Whether a volumetric split is used (<Nearly incompressible solves>).
    bool         mixed_solves;

    const StiffnessOperator              *stiffness = nullptr;
    /// K = A + B^T C^-1 B for a nearly incompressible body (else empty).
    VolumetricSplit                       split;
    /// The K (and split) the preconditioners were built from.
    const StiffnessOperator              *preconditioner_stiffness = nullptr;
    VolumetricSplit                       preconditioner_split;
    std::vector<std::vector<double>>      modes;
    double                                max_diagonal = 0;
    /// A lower bound for K's spectrum (0 if unknown), to judge shifts.
    double                                stiffness_floor = 0;

    /// One AMG for the elastic problem (sigma = 0) and one for the shifted
    /// problems of the primal steps, so that alternating between them
    /// does not rebuild either.
    AMG elastic_amg;
    AMG shifted_amg;
    /// The AMG of K with springs, for the Newton systems.
    SpringAMG spring_amg;
    bool      spring_amg_tried = false;

    /// The factorization of K + sigma_ref I for the shifted solves, whether
    /// K can be factored here (it lives on one process), and whether its
    /// factor is sparse enough to be used (known once it is analyzed).
    ShiftedCholesky cholesky;
    bool            factorizable         = false;
    bool            factor_sparse_enough = false;

    Vector diagonal;
    Vector inverse_diagonal;
    double jacobi_sigma = -1;

    const SpringPreconditioner *geometric_cycle        = nullptr;
    SpringPreconditioner       *geometric_with_springs = nullptr;
  };
} // namespace FrictionalContact
