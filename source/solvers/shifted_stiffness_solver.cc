#include <deal.II/base/timer.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <frictional_contact/base/input.h>
#include <frictional_contact/solvers/shifted_stiffness_solver.h>

#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>

#include <cmath>
#include <sstream>

namespace FrictionalContact
{
  namespace
  {
    /// The operator x -> (K + sigma I) x.
    class ShiftedOperator
    {
    public:
      ShiftedOperator(const StiffnessOperator &K, const double sigma)
        : K(K)
        , sigma(sigma)
      {}

      void
      vmult(TrilinosWrappers::MPI::Vector       &dst,
            const TrilinosWrappers::MPI::Vector &src) const
      {
        K.vmult(dst, src);
        if (sigma != 0)
          dst.add(sigma, src);
      }

    private:
      const StiffnessOperator &K;
      const double             sigma;
    };

    /// Multiplication by a stored inverse diagonal.
    class DiagonalPreconditioner
    {
    public:
      explicit DiagonalPreconditioner(const TrilinosWrappers::MPI::Vector &d)
        : inverse_diagonal(d)
      {}

      void
      vmult(TrilinosWrappers::MPI::Vector       &dst,
            const TrilinosWrappers::MPI::Vector &src) const
      {
        dst = src;
        dst.scale(inverse_diagonal);
      }

    private:
      const TrilinosWrappers::MPI::Vector &inverse_diagonal;
    };
  } // namespace



  void
  ShiftedStiffnessSolver::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    prm.declare_entry("Relative tolerance",
                      "1e-10",
                      Patterns::Double(0., 1.),
                      "CG reduces the residual of an elastic solve (a scene "
                      "without contact, and the solves inside the "
                      "eigenvalue computation) by this factor. The primal "
                      "steps of the contact solver have their own tolerance, "
                      "<Contact solver/Accelerated primal-dual/Primal step "
                      "tolerance>.");
    prm.declare_entry("Maximum iterations",
                      "10000",
                      Patterns::Integer(1),
                      "CG iterations allowed per solve (>= 1).");
    prm.declare_entry("Preconditioner",
                      "auto",
                      Patterns::Selection("auto|amg|jacobi|cholesky|geometric multigrid"),
                      "auto: for the primal steps (K + sigma I with sigma = "
                      "1/beta), Jacobi while max diag(K) <= Jacobi threshold "
                      "* sigma, else a sparse Cholesky factorization of K + "
                      "sigma_ref I (CHOLMOD) on one process if its factor "
                      "has at most 12 times the nonzeros of K, else AMG; for "
                      "the elastic solves AMG. A 3D mesh that fits in 80 % "
                      "of the available memory only without the assembled "
                      "K takes geometric multigrid and Matrix-free stiffness "
                      "instead (one line says so; not for B-bar bodies and "
                      "contact pairs). amg: always Trilinos ML. "
                      "jacobi: always the diagonal. cholesky: the "
                      "factorization for every solve on one process (AMG "
                      "on several). geometric multigrid: for the elastic "
                      "solves and the Newton systems a V-cycle on the levels "
                      "of the mesh (matrix-free, Chebyshev smoothing; for a "
                      "B-bar body the cycle of its compressible part in the "
                      "mixed solves, AMG with condensed solves), for the primal "
                      "steps Jacobi or the Cholesky factor as auto, else the "
                      "V-cycle of K.");
    prm.declare_entry("Multigrid smoother degree",
                      "2",
                      Patterns::Integer(1, 10),
                      "Preconditioner = geometric multigrid: the degree of "
                      "the Chebyshev smoother on each level (matrix-vector "
                      "products per smoothing, before and after the coarse "
                      "correction).");
    prm.declare_entry("Matrix-free stiffness",
                      "false",
                      Patterns::Bool(),
                      "true: K is never assembled; every product with it is "
                      "matrix-free (as on the multigrid's levels): at d >= "
                      "1M about a third of the memory per unknown of the "
                      "ML path, so about three times the unknowns fit "
                      "(doc/performance.md, \"Geometric multigrid\"). Needs "
                      "Preconditioner = geometric multigrid (Kanno's primal "
                      "steps then take Jacobi or the V-cycle of K, as ML "
                      "and the Cholesky factor need K's entries); not for "
                      "B-bar bodies, contact pairs or --fclib-export. "
                      "Preconditioner = auto sets it where only this path "
                      "fits in memory.");
    prm.declare_entry("Cholesky refactorization factor",
                      "1.5",
                      Patterns::Double(1.),
                      "The factorization of K + sigma_ref I preconditions "
                      "the primal steps while their shift sigma = 1/beta "
                      "stays within this factor of sigma_ref (>= 1): CG "
                      "needs more iterations the larger it is, and a "
                      "refactorization costs about as much as 40 solves "
                      "with the factor.");
    prm.declare_entry("Jacobi threshold",
                      "50",
                      Patterns::Double(0.),
                      "See Preconditioner = auto: how strongly the identity "
                      "term of beta K + I must dominate for Jacobi (>= 0). "
                      "Jacobi's iterations grow as the square root of max "
                      "diag(K) / sigma; at 20 (the paper's examples) it is "
                      "faster than AMG and Cholesky, at 200 it is slower "
                      "(doc/performance.md, \"Kanno's method\").");
    prm.declare_entry("AMG rebuild factor",
                      "2",
                      Patterns::Double(1.),
                      "The AMG built for K + sigma_ref I is reused while the "
                      "shift sigma = 1/beta stays within this factor of "
                      "sigma_ref (>= 1).");
    prm.declare_entry("Tangent rebuild factor",
                      "2",
                      Patterns::Double(0.),
                      "For nonlinear laws (plasticity, finite strain), whose "
                      "tangent drifts from the stiffness the preconditioner "
                      "was built on: it is built again on the tangent where "
                      "an increment starts once the last solve took more "
                      "than this factor times the Krylov iterations per "
                      "Newton step of the first solve after the last build "
                      "(0: never; not with geometric multigrid).");
    prm.declare_entry("AMG smoother sweeps",
                      "2",
                      Patterns::Integer(1),
                      "Smoother sweeps on each level of the AMG (>= 1).");
    prm.declare_entry("AMG smoother type",
                      "Chebyshev",
                      Patterns::Selection("Chebyshev|symmetric Gauss-Seidel"),
                      "The smoother on each level of the AMG: Chebyshev, or "
                      "symmetric Gauss-Seidel (with which the Newton method "
                      "takes the AMG of K without its node conditions).");
    prm.declare_entry("AMG coarse solver",
                      "auto",
                      Patterns::Selection("auto|MUMPS|KLU"),
                      "The direct solver of ML's coarsest level (Amesos), "
                      "which the Newton method's preconditioner refactors at "
                      "every change of the node conditions and applies at "
                      "every Krylov iteration: the multifrontal MUMPS or KLU, "
                      "deal.II's default. auto: KLU in 2D, MUMPS in 3D. The "
                      "coarsest levels of 3D elasticity are dense enough for "
                      "MUMPS to factor them faster; in 2D, MUMPS's fixed cost "
                      "per call outweighs its solve (doc/performance.md, "
                      "\"The coarse solver\").");
    prm.declare_entry("AMG near null space",
                      "rigid body modes",
                      Patterns::Selection("rigid body modes|translations"),
                      "The modes ML's aggregation preserves: all rigid-body "
                      "modes (translations and rotations) or translations "
                      "only, as DoFTools::extract_constant_modes gives.");
    prm.declare_entry(
      "Nearly incompressible solves",
      "mixed",
      Patterns::Selection("mixed|condensed"),
      "How a B-bar body with a bulk modulus above that of nu = 0.4 is "
      "solved. mixed: GMRES on the mixed system [A B^T; B -C] (A the "
      "stiffness at nu = 0.4, B the cells' divergence integrals, C their "
      "compliances), preconditioned by the AMG of A and a diagonal Schur "
      "complement; its iterations hardly grow with the bulk modulus. "
      "condensed: CG (or GMRES) on K itself, as for any other body, whose "
      "iterations grow as sqrt(bulk modulus / shear modulus) "
      "(doc/performance.md, \"Nearly incompressible bodies\").");
    prm.declare_entry("AMG aggregation threshold",
                      "1e-4",
                      Patterns::Double(0., 1.),
                      "ML's aggregation drop tolerance, in [0, 1].");
    prm.declare_entry("AMG prolongator damping",
                      "1.333",
                      Patterns::Double(0., 2.),
                      "ML's damping factor of the prolongator smoothing "
                      "(smoothed aggregation, 4/3 by default). 0: plain "
                      "aggregation, which needs far less memory for the "
                      "coarse levels but more Krylov iterations "
                      "(doc/performance.md).");
    prm.leave_subsection();
  }



  ShiftedStiffnessSolver::ShiftedStiffnessSolver(ParameterHandler  &prm,
                                                 const unsigned int dim)
    : dim(dim)
  {
    prm.enter_subsection("Linear solver");
    rel_tolerance         = prm.get_double("Relative tolerance");
    max_iterations        = prm.get_integer("Maximum iterations");
    preconditioner_choice = prm.get("Preconditioner");
    jacobi_threshold      = prm.get_double("Jacobi threshold");
    multigrid_degree      = prm.get_integer("Multigrid smoother degree");
    rebuild_factor        = prm.get_double("AMG rebuild factor");
    tangent_rebuild       = prm.get_double("Tangent rebuild factor");
    refactorization_factor = prm.get_double("Cholesky refactorization factor");
    smoother_sweeps       = prm.get_integer("AMG smoother sweeps");
    smoother_type         = prm.get("AMG smoother type");
    const std::string coarse = prm.get("AMG coarse solver");
    coarse_solver = "Amesos-" + (coarse != "auto" ? coarse : dim == 2 ? "KLU" : "MUMPS");
    aggregation_threshold = prm.get_double("AMG aggregation threshold");
    prolongator_damping   = prm.get_double("AMG prolongator damping");
    translations_only = prm.get("AMG near null space") == "translations";
    mixed_solves      = prm.get("Nearly incompressible solves") == "mixed";
    prm.leave_subsection();
  }



  void
  ShiftedStiffnessSolver::initialize(
    const StiffnessOperator          &K,
    std::vector<std::vector<double>>  rigid_body_modes,
    const double                      smallest_eigenvalue_estimate,
    const VolumetricSplit            &volumetric)
  {
    stiffness                = &K;
    preconditioner_stiffness = &K;
    split                = mixed_solves ? volumetric : VolumetricSplit();
    preconditioner_split = split;
    modes            = std::move(rigid_body_modes);
    spring_amg_tried = false;
    stiffness_floor = smallest_eigenvalue_estimate;
    elastic_amg.sigma = -1;
    shifted_amg.sigma = -1;
    jacobi_sigma      = -1;
    cholesky.clear();
    factorizable = K.is_assembled() && ShiftedCholesky::applicable(K.matrix(""));

    diagonal.reinit(K.locally_owned_domain_indices(), K.get_mpi_communicator());
    for (const auto i : K.locally_owned_domain_indices())
      diagonal[i] = K.diag_element(i);
    diagonal.compress(VectorOperation::insert);
    max_diagonal = diagonal.linfty_norm();
    inverse_diagonal.reinit(diagonal);
  }



  void
  ShiftedStiffnessSolver::replace_matrix(const StiffnessOperator &K,
                                         const VolumetricSplit   &volumetric)
  {
    stiffness = &K;
    split     = mixed_solves ? volumetric : VolumetricSplit();
  }



  void
  ShiftedStiffnessSolver::release()
  {
    geometric_cycle        = nullptr;
    geometric_with_springs = nullptr;
    spring_amg.clear();
    spring_amg_tried = false;
    elastic_amg.preconditioner.clear();
    shifted_amg.preconditioner.clear();
    cholesky.clear();
    elastic_amg.sigma = -1;
    shifted_amg.sigma = -1;
    jacobi_sigma      = -1;
    stiffness                = nullptr;
    preconditioner_stiffness = nullptr;
    split                    = {};
    preconditioner_split     = {};
  }



  void
  ShiftedStiffnessSolver::set_geometric_multigrid(const SpringPreconditioner *of_stiffness,
                                                  SpringPreconditioner *with_springs)
  {
    geometric_cycle        = of_stiffness;
    geometric_with_springs = with_springs;
  }



  bool
  ShiftedStiffnessSolver::use_geometric_multigrid(const double sigma) const
  {
    return sigma == 0 && preconditioner_choice == "geometric multigrid" &&
           geometric_cycle != nullptr;
  }



  bool
  ShiftedStiffnessSolver::use_jacobi(const double sigma) const
  {
    if (preconditioner_choice == "jacobi")
      return true;
    if (preconditioner_choice == "amg" || preconditioner_choice == "cholesky" ||
        use_geometric_multigrid(sigma))
      return false;
    return max_diagonal <= jacobi_threshold * sigma;
  }



  bool
  ShiftedStiffnessSolver::use_cholesky(const double sigma)
  {
    // auto: for the primal steps only; cholesky: for every solve.
    const bool wanted = preconditioner_choice == "cholesky" ||
                        ((preconditioner_choice == "auto" ||
                          preconditioner_choice == "geometric multigrid") &&
                         sigma > 0);
    if (!wanted || volumetric_split() != nullptr || !factorizable)
      return false;
    if (!cholesky.analyzed())
      {
        const Timer timer;
        const TrilinosWrappers::SparseMatrix &K =
          preconditioner_stiffness->matrix("the Cholesky factor");
        cholesky.analyze(K);
        factorization_seconds += timer.wall_time();
        // A factor much denser than K (3D beyond some 10^5 unknowns) costs
        // more per solve than the AMG's V-cycle, and memory.
        factor_sparse_enough =
          preconditioner_choice == "cholesky" ||
          cholesky.predicted_factor_nonzeros() <=
            12. * K.n_nonzero_elements();
      }
    return factor_sparse_enough;
  }



  const ShiftedCholesky &
  ShiftedStiffnessSolver::cholesky_for(const double sigma)
  {
    const double reference = cholesky.shift();
    if (sigma == reference ||
        (reference > 0 && sigma >= reference / refactorization_factor &&
         sigma <= reference * refactorization_factor))
      return cholesky;
    const Timer timer;
    cholesky.factorize(sigma);
    ++n_factorizations;
    factorization_seconds += timer.wall_time();
    return cholesky;
  }



  void
  ShiftedStiffnessSolver::build_jacobi(const double sigma)
  {
    if (sigma == jacobi_sigma)
      return;
    double *inverse = inverse_diagonal.begin();
    const double *d = diagonal.begin();
    for (unsigned int i = 0; i < diagonal.locally_owned_size(); ++i)
      inverse[i] = 1. / (d[i] + sigma);
    jacobi_sigma = sigma;
  }



  const TrilinosWrappers::PreconditionAMG &
  ShiftedStiffnessSolver::amg_for(const double sigma)
  {
    AMG &amg = sigma == 0 ? elastic_amg : shifted_amg;
    if (amg.sigma >= 0 &&
        std::abs(sigma - amg.sigma) <=
          (rebuild_factor - 1.) * (std::min(sigma, amg.sigma) + stiffness_floor))
      return amg.preconditioner;

    Timer timer;
    amg.preconditioner.clear(); // ML keeps a reference to its matrix
    // Without a shift the AMG is built on K (or A) itself, without a copy.
    if (sigma != 0)
      {
        amg.matrix.copy_from(amg_matrix());
        for (const auto i : stiffness->locally_owned_domain_indices())
          amg.matrix.add(i, i, sigma);
        amg.matrix.compress(VectorOperation::add);
      }
    const TrilinosWrappers::SparseMatrix &matrix =
      sigma != 0 ? amg.matrix : amg_matrix();

    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = false;
    data.smoother_sweeps       = smoother_sweeps;
    data.smoother_type         = smoother_type.c_str();
    data.coarse_type           = coarse_solver.c_str();
    data.aggregation_threshold = aggregation_threshold;

    Teuchos::ParameterList              parameters;
    std::unique_ptr<Epetra_MultiVector> unused_constant_modes;
    data.set_parameters(parameters, unused_constant_modes, matrix);

    // Near null space: the rigid-body modes, nodal blocks of dim dofs.
    const unsigned int n_modes = n_null_space_modes();
    Epetra_MultiVector null_space(matrix.trilinos_matrix().OperatorDomainMap(),
                                  n_modes);
    for (unsigned int m = 0; m < n_modes; ++m)
      for (unsigned int row = 0; row < modes[m].size(); ++row)
        null_space[m][row] = modes[m][row];
    parameters.set("PDE equations", static_cast<int>(dim));
    parameters.set("aggregation: damping factor", prolongator_damping);
    parameters.set("null space: type", "pre-computed");
    parameters.set("null space: dimension", static_cast<int>(n_modes));
    parameters.set("null space: vectors", null_space.Values());
    // The list is deal.II's and ours, known to be valid: checking it took
    // ML 2 to 3 ms per hierarchy, an eighth of an update at d = 7,260.
    parameters.set("ML validate parameter list", false);

    amg.preconditioner.initialize(matrix, parameters);
    amg.sigma = sigma;
    ++n_amg_setups;
    amg_setup_seconds += timer.wall_time();
    return amg.preconditioner;
  }



  unsigned int
  ShiftedStiffnessSolver::n_null_space_modes() const
  {
    return translations_only ? std::min<unsigned int>(dim, modes.size()) :
                               modes.size();
  }



  SpringPreconditioner &
  ShiftedStiffnessSolver::spring_preconditioner()
  {
    if (newton_uses_geometric_multigrid())
      return *geometric_with_springs;
    // Its fine level smooths as ML's Chebyshev does; with another
    // smoother the Newton method keeps the AMG of K.
    if (!spring_amg_tried && !use_jacobi(0.) && !use_geometric_multigrid(0.) &&
        smoother_type == "Chebyshev")
      {
        const auto &amg = amg_for(0.);
        const std::vector<std::vector<double>> used_modes(
          modes.begin(), modes.begin() + n_null_space_modes());
        spring_amg.initialize(amg_matrix(), amg, used_modes, smoother_sweeps);
        spring_amg_tried = true;
      }
    return spring_amg;
  }



  void
  ShiftedStiffnessSolver::prepare_stiffness_preconditioner()
  {
    if (use_geometric_multigrid(0.))
      last_linear_solve = "CG iterations (geometric multigrid)";
    else if (use_jacobi(0.))
      {
        build_jacobi(0.);
        last_linear_solve = "CG iterations (Jacobi)";
      }
    else
      {
        amg_for(0.);
        last_linear_solve = "CG iterations (AMG)";
      }
  }



  void
  ShiftedStiffnessSolver::precondition_stiffness(Vector       &dst,
                                                 const Vector &src) const
  {
    if (use_geometric_multigrid(0.))
      geometric_cycle->vmult(dst, src);
    else if (use_jacobi(0.))
      DiagonalPreconditioner(inverse_diagonal).vmult(dst, src);
    else
      elastic_amg.preconditioner.vmult(dst, src);
  }



  unsigned int
  ShiftedStiffnessSolver::solve(const double  sigma,
                                Vector       &x,
                                const Vector &b,
                                const double  tolerance)
  {
    SolverControl         control(max_iterations, tolerance, false, false);
    const ShiftedOperator op(*stiffness, sigma);
    const auto cg_solve = [&](const auto        &preconditioner,
                              const std::string &name) -> unsigned int {
      last_linear_solve = "CG iterations (" + name + ")";
      const Timer timer;
      SolverCG<Vector>(control).solve(op, x, b, preconditioner);
      krylov_seconds += timer.wall_time();
      return control.last_step();
    };
    // CG with K + sigma I, or GMRES on the mixed form where K has a split
    // (the preconditioner then being that of the split's A).
    const auto krylov_solve = [&](const auto        &preconditioner,
                                  const std::string &name,
                                  const bool         variable) -> unsigned int {
      if (volumetric_split() == nullptr)
        return cg_solve(preconditioner, name);
      last_linear_solve = "GMRES iterations (" + name + ", mixed form)";
      const Timer timer;
      const auto  shift = [sigma](Vector &force, const Vector &u) {
        if (sigma != 0)
          force.add(sigma, u);
      };
      Vector     residual(b);
      const auto true_residual = [&](const Vector &u) {
        op.vmult(residual, u);
        residual -= b;
        return residual.l2_norm();
      };
      const unsigned int iterations = MixedVolumetric::solve(
        split, shift, preconditioner, variable, true_residual,
        max_iterations, tolerance, x, b);
      krylov_seconds += timer.wall_time();
      return iterations;
    };
    try
      {
        if (use_jacobi(sigma))
          {
            build_jacobi(sigma);
            return cg_solve(DiagonalPreconditioner(inverse_diagonal), "Jacobi");
          }
        if (use_cholesky(sigma))
          return cg_solve(cholesky_for(sigma), "Cholesky");
        // The cycle of K (or A) serves K + sigma I too (a primal step that
        // Jacobi and the factor leave), relative to which K + sigma I has
        // its spectrum in [1, 1 + sigma / lambda_min(K)].
        if (use_geometric_multigrid(0.))
          return krylov_solve(*geometric_cycle,
                              sigma == 0 ? "geometric multigrid" :
                                           "geometric multigrid of K",
                              true);
        return krylov_solve(amg_for(sigma), "AMG", false);
      }
    catch (const SolverControl::NoConvergence &e)
      {
        std::ostringstream message;
        message << "the " << (volumetric_split() != nullptr ? "GMRES" : "conjugate gradient") << " solve of (K + " << sigma
                << " I) x = b did not converge: residual " << e.last_residual
                << " after " << e.last_step << " iterations, tolerance "
                << tolerance << " (" << last_linear_solve
                << " preconditioner). Try a larger <Linear solver/Maximum "
                   "iterations> or <Linear solver/Relative tolerance>";
        throw SolverError(message.str());
      }
  }
} // namespace FrictionalContact
