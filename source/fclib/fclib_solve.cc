#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <frictional_contact/fclib/fclib_export.h>
#include <frictional_contact/fclib/fclib_newton.h>
#include <frictional_contact/fclib/fclib_solve.h>
#include <frictional_contact/base/input.h>
#include <frictional_contact/base/plugins.h>
#include <frictional_contact/solvers/stiffness_spectrum.h>

#include <iomanip>
#include <sstream>

namespace FrictionalContact
{
  namespace
  {
    /// Problems up to this size get the eigenvalues of M from LAPACK.
    constexpr unsigned int largest_dense_size = 1000;

    /// Preconditioner = auto: problems up to this size take the sparse LU
    /// path (Jacobi for Kanno's method). Measured (doc/fclib.md): on the
    /// files of our 3D scenes, the LU path is faster at n = 972 and 675,
    /// ML's 10 times faster at n = 4,131.
    constexpr unsigned int largest_size_without_amg = 2000;

    /// Whether each contact's rows of H are the dim rows of one node (rows
    /// dim k to dim k + dim - 1) that no other contact has: the contacts of
    /// an elastic body on a mesh, as our semismooth Newton method takes
    /// them (not several contacts on one rigid body).
    bool
    contacts_on_own_nodes(const FclibProblem &fclib)
    {
      const unsigned int d = fclib.spacedim;
      std::vector<int>   contact_of_node(fclib.n / d + 1, -1);
      std::vector<int>   node_of_contact(fclib.n_contacts(), -1);
      for (const auto &e : fclib.H)
        {
          const int node = e.row / d, contact = e.column / d;
          if ((contact_of_node[node] >= 0 && contact_of_node[node] != contact) ||
              (node_of_contact[contact] >= 0 && node_of_contact[contact] != node))
            return false;
          contact_of_node[node]    = contact;
          node_of_contact[contact] = node;
        }
      return true;
    }
  } // namespace



  template <int dim>
  bool
  FclibSolve<dim>::choose_preconditioner(ParameterHandler &prm) const
  {
    prm.enter_subsection("Contact solver");
    const bool newton = prm.get("Method") == "semismooth Newton";
    prm.leave_subsection();
    prm.enter_subsection("Linear solver");
    const std::string choice = prm.get("Preconditioner");
    prm.leave_subsection();
    if (choice == "geometric multigrid" ||
        (choice == "cholesky" &&
         Utilities::MPI::n_mpi_processes(mpi_communicator) > 1))
      Input::fail("Linear solver/Preconditioner",
                  choice,
                  "auto, amg, jacobi, or cholesky on one process: an FCLIB "
                  "problem has no mesh for the multigrid");

    // What the AMG path needs: nodes of dim unknowns (the translations are
    // its near null space), M symmetric for CG, and for the Newton method
    // contacts on nodes of their own.
    const bool   amg_considered =
      choice == "amg" || (choice == "auto" && fclib.n > largest_size_without_amg);
    const double asymmetric =
      (amg_considered || !newton) ? asymmetry(fclib.M) : 0;
    const bool        symmetric = asymmetric <= largest_symmetric_asymmetry;
    const std::string by_how_much =
      "(max |m_ij - m_ji| / sqrt(|m_ii m_jj|) = " + Input::to_text(asymmetric) + ")";
    if (!newton && !symmetric)
      throw InputError("the FCLIB file '" + file_name +
                       "' has a matrix M that is not symmetric " + by_how_much +
                       "; Kanno's method needs M symmetric positive "
                       "definite: use <Contact solver/Method> = semismooth "
                       "Newton");
    std::string why_not;
    if (fclib.n % dim != 0)
      why_not = "the AMG takes the unknowns as nodes of " +
                std::to_string(dim) + " components, and the file has " +
                std::to_string(fclib.n) + " unknowns";
    else if (!symmetric)
      why_not = "M is not symmetric " + by_how_much + " and the AMG path solves with conjugate gradients";
    else if (newton && !contacts_on_own_nodes(fclib))
      why_not = "contacts share nodes (several contacts on one body, say), "
                "and the semismooth Newton method's AMG path takes each "
                "contact on a node of its own";

    if (choice == "amg" && !why_not.empty())
      Input::fail("Linear solver/Preconditioner",
                  choice,
                  why_not + "; use jacobi (with which the semismooth Newton "
                  "method factorizes M)");
    if (choice != "auto")
      return choice == "amg";
    // auto: the AMG path for problems of finite-element size that it
    // takes, Jacobi (and the sparse LU for the Newton method) otherwise.
    const bool amg = why_not.empty() && fclib.n > largest_size_without_amg;
    if (!amg)
      {
        prm.enter_subsection("Linear solver");
        prm.set("Preconditioner", "jacobi");
        prm.leave_subsection();
      }
    return amg;
  }



  template <int dim>
  FclibSolve<dim>::FclibSolve(ParameterHandler  &prm,
                              FclibProblem       problem,
                              const std::string &file_name,
                              const MPI_Comm     comm)
    : mpi_communicator(comm)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
    , fclib(std::move(problem))
    , file_name(file_name)
    , owned(fclib.n)
    , with_amg(choose_preconditioner(prm))
    , linear_solver(prm, dim)
    , solver(prm, pcout)
  {
    AssertThrow(fclib.spacedim == dim, ExcInternalError());
    // Rank 0 holds everything.
    const bool root = Utilities::MPI::this_mpi_process(comm) == 0;
    if (root)
      owned.add_range(0, fclib.n);
    TrilinosWrappers::SparsityPattern pattern(owned, comm);
    if (root)
      for (const auto &e : fclib.M)
        pattern.add(e.row, e.column);
    pattern.compress();
    M.reinit(pattern);
    if (root)
      for (const auto &e : fclib.M)
        M.add(e.row, e.column, e.value);
    M.compress(VectorOperation::add);
    f = to_vector(fclib.f);

    // T = H with the normal columns negated (doc/fclib.md).
    std::vector<std::array<typename SparseContactMap<dim>::Column, dim>>
      columns(root ? fclib.n_contacts() : 0);
    if (root)
      for (const auto &e : fclib.H)
        {
          const unsigned int k = e.column % dim;
          columns[e.column / dim][k].emplace_back(e.row,
                                                  k == 0 ? -e.value : e.value);
        }
    contact = std::make_unique<SparseContactMap<dim>>(std::move(columns),
                                                      fclib.mu[0],
                                                      owned,
                                                      comm);
    linear_solver.initialize(M_operator, translations());
  }



  template <int dim>
  std::vector<std::vector<double>>
  FclibSolve<dim>::translations() const
  {
    // Unknown i is component i % dim of its node, as in the files this
    // program exports (deal.II numbers the dofs of a vertex together).
    std::vector<std::vector<double>> modes(dim,
                                           std::vector<double>(owned.n_elements()));
    for (unsigned int i = 0; i < owned.n_elements(); ++i)
      modes[i % dim][i] = 1;
    return modes;
  }



  template <int dim>
  IncrementalProblem<dim>
  FclibSolve<dim>::incremental_problem() const
  {
    IncrementalProblem<dim> problem{M_operator, f, *contact};
    for (unsigned int j = 0; j < contact->n_local(); ++j)
      {
        problem.gaps.push_back(fclib.w[dim * j]);
        Tensor<1, dim> slip;
        for (unsigned int k = 1; k < dim; ++k)
          slip[k] = -fclib.w[dim * j + k];
        problem.obstacle_slip.push_back(slip);
      }
    return problem;
  }



  template <int dim>
  void
  FclibSolve<dim>::solve(const std::string &solution_file)
  {
    pcout << "FCLIB problem " << file_name
          << (fclib.title.empty() ? "" : " (" + fclib.title + ")") << ":\n"
          << "    n = " << fclib.n << " unknowns, " << fclib.n_contacts()
          << " contacts in " << dim << "D, mu = "
          << Input::to_text(fclib.mu[0]) << std::endl;

    // The semismooth Newton method has its own form for FCLIB's arrays
    // (FclibNewton, with a sparse LU) unless the AMG is asked for; any
    // other method runs as a plugin on our form of the problem.
    const Outcome outcome =
      solver.method_name == "semismooth Newton" && !with_amg ?
        solve_by_newton() :
        solve_by_plugin();
    pcout << (outcome.converged ? "Converged" : "Not converged") << " after "
          << outcome.iterations << ' ' << solver.method->iteration_name()
          << " iterations";
    if (outcome.linear_iterations > 0)
      pcout << " (" << outcome.linear_iterations << " Krylov iterations)";
    pcout << std::endl;
    const auto [res, error] = report(outcome.solution);
    pcout << "FCLIB result: method=" << solver.method_name
          << " converged=" << outcome.converged
          << " iterations=" << outcome.iterations
          << " seconds=" << outcome.seconds
          << " error=" << Input::scientific(error) << std::endl;
    if (!outcome.converged)
      throw SolverError(outcome.failure + ". Residuals: force balance " +
                        Input::scientific(res.force_balance) +
                        ", complementarity " +
                        Input::scientific(res.complementarity) +
                        ", penetration " + Input::scientific(res.penetration) +
                        "; no solution written");

    if (!solution_file.empty())
      {
        write_fclib(mpi_communicator, solution_file, fclib, &outcome.solution);
        pcout << "Wrote the problem and its solution to " << solution_file
              << std::endl;
      }
  }



  template <int dim>
  typename FclibSolve<dim>::Outcome
  FclibSolve<dim>::solve_by_newton() const
  {
    const StoppingRule &stop = solver.method->stopping_rule();
    pcout << "Solver: semismooth Newton (Alart-Curnier, sparse Cholesky or LU), stop at "
             "FCLIB error <= "
          << Input::to_text(stop.tolerance) << std::endl;
    FclibNewton::Result result =
      FclibNewton(fclib).solve(stop.tolerance, stop.max_iterations);
    Outcome outcome;
    outcome.converged  = result.converged;
    outcome.iterations = result.iterations;
    outcome.seconds    = result.seconds;
    outcome.failure    = "the solve failed: " + result.failure;
    outcome.solution   = std::move(result.solution);
    return outcome;
  }



  template <int dim>
  typename FclibSolve<dim>::Outcome
  FclibSolve<dim>::solve_by_plugin()
  {
    // Counted from here: the spectral constants, the free velocity and the
    // preconditioners' set-ups are part of the solve.
    const Timer             wall;
    IncrementalProblem<dim> problem = incremental_problem();
    problem.largest_singular_value_T = contact->largest_singular_value();
    if (solver.method->needs_smallest_eigenvalue())
      {
        problem.smallest_eigenvalue_K = smallest_eigenvalue_of_M();
        pcout << "    smallest eigenvalue of M = "
              << Input::scientific(problem.smallest_eigenvalue_K)
              << ", largest singular value of H = "
              << Input::scientific(problem.largest_singular_value_T)
              << std::endl;
        if (!(problem.smallest_eigenvalue_K > 0))
          throw InputError("the FCLIB file '" + file_name +
                           "' has a matrix M that is not positive definite "
                           "(smallest eigenvalue " +
                           Input::scientific(problem.smallest_eigenvalue_K) +
                           ")");
      }

    // The length scale: the largest |w| or free velocity M^{-1} f (to three
    // digits: it scales the tolerances).
    Vector free_velocity(f);
    free_velocity = 0;
    linear_solver.solve(0., free_velocity, f, 1e-3 * f.l2_norm());
    double largest_w = 0;
    for (const double w_i : fclib.w)
      largest_w = std::max(largest_w, std::abs(w_i));
    problem.length_scale = std::max(largest_w, free_velocity.linfty_norm());
    if (!(problem.length_scale > 0))
      problem.length_scale = 1;

    pcout << "Solver: " << solver.method->describe() << std::endl;
    if (with_amg)
      pcout << "Linear solver: CG with ML on M (the translations as near "
               "null space)"
            << std::endl;
    Vector                      du(f);
    std::vector<Tensor<1, dim>> r(contact->n_local());
    du = 0;
    const SolveStatistics result =
      solver.method->solve(problem, linear_solver, du, r, false);
    Outcome outcome;
    outcome.converged         = result.converged;
    outcome.iterations        = result.iterations;
    outcome.linear_iterations = result.linear_iterations;
    outcome.seconds           = wall.wall_time();
    pcout << "    seconds: " << Input::to_text(outcome.seconds) << " (AMG set-ups "
          << Input::to_text(linear_solver.amg_setup_wall_time())
          << ", Krylov solves " << Input::to_text(linear_solver.krylov_seconds)
          << ")" << std::endl;
    outcome.failure           = result.failure;
    outcome.solution          = to_fclib(du, r);
    return outcome;
  }



  template <int dim>
  double
  FclibSolve<dim>::smallest_eigenvalue_of_M()
  {
    if (fclib.n > largest_dense_size)
      return compute_smallest_eigenvalue(M_operator,
                                         linear_solver,
                                         solver.eigenvalue_tolerance,
                                         solver.lanczos_vectors)
        .value;
    double smallest = 0;
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      {
        LAPACKFullMatrix<double> dense(fclib.n, fclib.n);
        for (const auto &e : fclib.M)
          dense(e.row, e.column) += e.value;
        dense.compute_eigenvalues();
        smallest = std::numeric_limits<double>::max();
        for (unsigned int i = 0; i < fclib.n; ++i)
          smallest = std::min(smallest, dense.eigenvalue(i).real());
      }
    return Utilities::MPI::broadcast(mpi_communicator, smallest, 0);
  }



  template <int dim>
  void
  FclibSolve<dim>::evaluate(const std::string &solution_file,
                            const std::string &reference_file)
  {
    const FclibSolution solution = read_fclib_solution(solution_file, fclib);
    pcout << "Solution stored in " << solution_file << ":" << std::endl;
    report(solution);
    if (!reference_file.empty())
      {
        const FclibSolution reference =
          read_fclib_solution(reference_file, fclib);
        pcout << "Relative difference to the solution in " << reference_file
              << ": v " << Input::scientific(relative_difference(solution.v, reference.v))
              << ", r " << Input::scientific(relative_difference(solution.r, reference.r))
              << std::endl;
      }
  }



  template <int dim>
  std::pair<Residuals, double>
  FclibSolve<dim>::report(const FclibSolution &solution) const
  {
    // The residuals in our form: du = v, r = (-r_n, r_t).
    const IncrementalProblem<dim> problem = incremental_problem();
    const Vector                  du      = to_vector(solution.v);
    std::vector<Tensor<1, dim>>   r(contact->n_local());
    for (unsigned int j = 0; j < r.size(); ++j)
      for (unsigned int k = 0; k < dim; ++k)
        r[j][k] = (k == 0 ? -1. : 1.) * solution.r[dim * j + k];
    Vector K_du(du), T_r(du), scratch(du);
    M.vmult(K_du, du);
    contact->apply(r, T_r);
    const Residuals res = compute_residuals(problem, du, K_du, T_r, r, scratch);
    const double    error = fclib_error(fclib, solution);
    pcout << "    residuals: force balance " << Input::scientific(res.force_balance)
          << ", complementarity " << Input::scientific(res.complementarity)
          << ", penetration " << Input::scientific(res.penetration) << std::endl
          << "FCLIB error: " << Input::scientific(error) << std::endl;
    return {res, error};
  }



  template <int dim>
  FclibSolution
  FclibSolve<dim>::to_fclib(const Vector                      &du,
                            const std::vector<Tensor<1, dim>> &r) const
  {
    FclibSolution solution;
    solution.v = to_std(du);
    for (const auto &r_j : r)
      for (unsigned int k = 0; k < dim; ++k)
        solution.r.push_back(k == 0 ? -r_j[k] : r_j[k]);
    solution.r = Utilities::MPI::broadcast(mpi_communicator, solution.r, 0);
    solution.u = local_velocity(fclib, solution.v);
    return solution;
  }



  template <int dim>
  typename FclibSolve<dim>::Vector
  FclibSolve<dim>::to_vector(const std::vector<double> &x) const
  {
    Vector vector(owned, mpi_communicator);
    double *entries = vector.begin();
    for (unsigned int i = 0; i < owned.n_elements(); ++i)
      entries[i] = x[i];
    return vector;
  }



  template <int dim>
  std::vector<double>
  FclibSolve<dim>::to_std(const Vector &x) const
  {
    const std::vector<double> local(x.begin(), x.end());
    return Utilities::MPI::broadcast(mpi_communicator, local, 0);
  }

  template class FclibSolve<2>;
  template class FclibSolve<3>;
} // namespace FrictionalContact
