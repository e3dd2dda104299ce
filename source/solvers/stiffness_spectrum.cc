#include <deal.II/lac/parpack_solver.h>
#include <deal.II/lac/solver_control.h>

#include <frictional_contact/base/input.h>
#include <frictional_contact/solvers/stiffness_spectrum.h>

#include <complex>

namespace FrictionalContact
{
  namespace
  {
    using Vector = TrilinosWrappers::MPI::Vector;

    class Identity
    {
    public:
      void
      vmult(Vector &dst, const Vector &src) const
      {
        dst = src;
      }
    };

    /// x = K^{-1} b by AMG-preconditioned CG, counting the work.
    class InverseStiffness
    {
    public:
      InverseStiffness(ShiftedStiffnessSolver &solver,
                       const double            relative_tolerance,
                       SmallestEigenvalue     &counters)
        : solver(solver)
        , relative_tolerance(relative_tolerance)
        , counters(counters)
      {}

      void
      vmult(Vector &dst, const Vector &src) const
      {
        dst = 0;
        counters.cg_iterations +=
          solver.solve(0., dst, src, relative_tolerance * src.l2_norm());
        ++counters.n_solves;
      }

    private:
      ShiftedStiffnessSolver &solver;
      const double            relative_tolerance;
      SmallestEigenvalue     &counters;
    };
  } // namespace



  SmallestEigenvalue
  compute_smallest_eigenvalue(const StiffnessOperator &stiffness,
                              ShiftedStiffnessSolver               &solver,
                              const double                          tolerance,
                              const unsigned int n_lanczos_vectors)
  {
    SmallestEigenvalue result;
    const IndexSet     owned = stiffness.locally_owned_domain_indices();
    const MPI_Comm     comm  = stiffness.get_mpi_communicator();

    // The inner solves must be more accurate than the eigenvalue.
    const InverseStiffness inverse(solver, 1e-2 * tolerance, result);

    SolverControl control(1000, tolerance, false, false);
    PArpackSolver<Vector>::AdditionalData data(
      std::min<unsigned int>(n_lanczos_vectors, owned.size() - 1),
      PArpackSolver<Vector>::largest_magnitude,
      /*symmetric=*/true,
      /*mode=*/3);
    PArpackSolver<Vector> eigensolver(control, comm, data);
    eigensolver.reinit(owned);
    eigensolver.set_shift(0.);

    // A smooth positive start vector speeds up the lowest (bending) mode.
    Vector start(owned, comm);
    start = 1.;
    eigensolver.set_initial_vector(start);

    std::vector<std::complex<double>> eigenvalues(1);
    std::vector<Vector>               eigenvectors(1, Vector(owned, comm));
    try
      {
        eigensolver.solve(stiffness, Identity(), inverse, eigenvalues, eigenvectors, 1);
      }
    catch (const std::exception &e)
      {
        throw SolverError(
          "PARPACK could not compute the smallest eigenvalue of K (" +
          std::string(e.what()).substr(0, 200) +
          "); try more <Contact solver/Lanczos vectors>");
      }
    result.value = eigenvalues[0].real();

    Vector Kx(owned, comm);
    stiffness.vmult(Kx, eigenvectors[0]);
    result.rayleigh_quotient =
      (Kx * eigenvectors[0]) / (eigenvectors[0] * eigenvectors[0]);
    return result;
  }
} // namespace FrictionalContact
