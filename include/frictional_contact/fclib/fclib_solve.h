#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <frictional_contact/solvers/contact_solver_parameters.h>
#include <frictional_contact/fclib/fclib_problem.h>
#include <frictional_contact/solvers/shifted_stiffness_solver.h>
#include <frictional_contact/solvers/sparse_contact_map.h>

#include <memory>
#include <string>

namespace FrictionalContact
{
  /**
   * The program's --fclib mode (doc/fclib.md): solves an FCLIB global
   * problem with the method of <Contact solver/Method>. The semismooth
   * Newton method (the default) works on FCLIB's own form with a sparse LU
   * (FclibNewton), or, on the AMG path (choose_preconditioner()), as the
   * accelerated primal-dual method always does: as a plugin on one
   * incremental problem in our form. Owns the problem (every rank has the file's arrays; rank 0
   * holds the matrices and all contacts), M in Trilinos format, the sparse
   * T, and the solvers chosen in the parameter file. Prints the paper's
   * three residuals and FCLIB's error measure.
   */
  template <int dim>
  class FclibSolve
  {
  public:

    FclibSolve(ParameterHandler  &prm,
               FclibProblem       problem,
               const std::string &file_name,
               const MPI_Comm     comm);

    /**
     * Solves from v = 0, r = 0 and reports. Writes the problem with its
     * solution to @p solution_file (if not empty). Throws a SolverError if
     * the solve does not converge.
     */
    void
    solve(const std::string &solution_file);

    /**
     * Reports the residuals and FCLIB's error measure of the solution
     * stored in @p solution_file, and its relative difference to the one
     * in @p reference_file (if not empty).
     */
    void
    evaluate(const std::string &solution_file,
             const std::string &reference_file);

  private:
    using Vector = TrilinosWrappers::MPI::Vector;

    /// What a method's solve gives, in FCLIB's form on every rank.
    struct Outcome
    {
      bool          converged         = false;
      unsigned int  iterations        = 0;
      unsigned int  linear_iterations = 0;
      double        seconds           = 0;
      std::string   failure;
      FclibSolution solution;
    };

    /// FclibNewton on the file's arrays (every rank solves the whole
    /// problem: no communication, the same result everywhere).
    Outcome
    solve_by_newton() const;

    /// The method's plugin on our form of the problem (Kanno's Algorithm 2,
    /// or any other method but the semismooth Newton one), with mu_pi
    /// computed if the method needs it and sigma_T.
    Outcome
    solve_by_plugin();

    /**
     * Whether the solves with M take ML (<Linear solver/Preconditioner> =
     * amg, or auto on a symmetric M of more than 2,000 unknowns in nodes
     * of dim, with each contact on a node of its own for the Newton
     * method); auto otherwise becomes jacobi in @p prm. Refuses what this
     * mode cannot do (the multigrid, an AMG it cannot build, Kanno's
     * method on a non-symmetric M).
     */
    bool
    choose_preconditioner(ParameterHandler &prm) const;

    /// The near null space of the AMG: the dim translations.
    std::vector<std::vector<double>>
    translations() const;

    /// mu_pi: LAPACK up to 1000 unknowns, PARPACK above.
    double
    smallest_eigenvalue_of_M();

    /// Our form of the problem (T = H with the normal column negated).
    IncrementalProblem<dim>
    incremental_problem() const;

    /// The solution (du, r) in FCLIB's form, on every rank.
    FclibSolution
    to_fclib(const Vector &du, const std::vector<Tensor<1, dim>> &r) const;

    /// Prints the residuals of (v, r) and FCLIB's error; returns both.
    std::pair<Residuals, double>
    report(const FclibSolution &solution) const;

    /// x on rank 0 as a Trilinos vector; and back, on every rank.
    Vector
    to_vector(const std::vector<double> &x) const;
    std::vector<double>
    to_std(const Vector &x) const;

    MPI_Comm                            mpi_communicator;
    ConditionalOStream                  pcout;
    FclibProblem                        fclib;
    std::string                         file_name;
    IndexSet                            owned;
    TrilinosWrappers::SparseMatrix      M;
    /// M as the solvers take it.
    AssembledStiffness                  M_operator{M};
    Vector                              f;
    std::unique_ptr<SparseContactMap<dim>> contact;
    /// Whether M's solves take ML (choose_preconditioner()); the
    /// semismooth Newton method then runs as a plugin on our form.
    const bool                          with_amg;
    ShiftedStiffnessSolver              linear_solver;
    ContactSolverParameters<dim>        solver;
  };
} // namespace FrictionalContact
