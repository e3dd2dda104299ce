#pragma once

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <frictional_contact/solvers/nodal_block.h>
#include <frictional_contact/solvers/spring_preconditioner.h>

#include <Teuchos_ParameterList.hpp>

#include <memory>
#include <vector>

class Amesos_BaseSolver;
class Epetra_CrsMatrix;
class Epetra_FECrsMatrix;
class Epetra_LinearProblem;
class Epetra_MultiVector;
class Epetra_Vector;
namespace ML_Epetra
{
  class MultiLevelPreconditioner;
}

namespace FrictionalContact
{
  using namespace dealii;

  class NodalBlockMatrix;

  /**
   * An AMG V-cycle for K + S, where S is a sum of small symmetric blocks on
   * the dofs of single nodes (the stiff springs that stand for the node
   * conditions of a Newton system), made so that S can change often and
   * cheaply. The hierarchy of K that Trilinos ML built is taken apart once:
   * its first prolongator P, its first coarse operator A_1 = P^T K P and the
   * rigid-body modes on that level. A new S then costs the coarse operator
   * A_1 + P^T S P (only the rows of P at the springs' nodes enter) and an
   * ML hierarchy for it, which is about a tenth of the size of K (or, when
   * A_1 is small enough for ML to factor it directly, a new numerical
   * factorization that keeps the first one's symbolic analysis); the fine
   * level smooths K + S itself (Chebyshev, as ML does, with the diagonal of
   * K + S), with K's products taken in single-precision nodal blocks
   * (NodalBlockMatrix) where K allows. Without springs the cycle is ML's
   * own. Owns the copies of P, A_1 and K, the coarse hierarchy and the
   * springs.
   */
  class SpringAMG : public SpringPreconditioner
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    SpringAMG();
    ~SpringAMG() override;

    /**
     * Takes the hierarchy of @p amg_of_K (Trilinos ML, built on @p K, which
     * must outlive this object, as must @p amg_of_K while initialize()
     * runs) apart; @p rigid_body_modes are the near null space it was built
     * with, @p smoother_sweeps the degree of the fine Chebyshev smoother.
     * The coarse hierarchies take the parameters of @p amg_of_K.
     */
    void
    initialize(const TrilinosWrappers::SparseMatrix    &K,
               const TrilinosWrappers::PreconditionAMG &amg_of_K,
               const std::vector<std::vector<double>>  &rigid_body_modes,
               const unsigned int                       smoother_sweeps);

    /// Whether initialize() succeeded (ML made at least two levels).
    bool
    initialized() const override
    {
      return coarse_matrix != nullptr;
    }

    /// Whether the first coarse level is factored directly (it has no more
    /// rows than ML's coarsest level) rather than given an ML hierarchy.
    bool
    factors_first_coarse_level() const
    {
      return direct_solver != nullptr;
    }

    /// Frees everything (before K changes).
    void
    clear();

    /// Makes the cycle for K + the sum of @p springs. Collective.
    void
    set_springs(const std::vector<NodalBlock> &springs) override;

    /// dst = one V-cycle for (K + S) dst = src, from dst = 0.
    void
    vmult(Vector &dst, const Vector &src) const override;

    /// Seconds spent in initialize() and set_springs(), all of them (clear()
    /// keeps the count).
    double setup_seconds = 0;

  private:
    /**
     * Takes P, A_1 and the coarse rigid-body modes from the ML hierarchy
     * of K (of at least two levels). Returns false if it cannot.
     */
    bool
    take_first_level(const ML_Epetra::MultiLevelPreconditioner &ml,
                     const std::vector<std::vector<double>>    &rigid_body_modes);

    /// The springs as entries of the fine matrix and its diagonal.
    void
    set_fine_springs(const std::vector<NodalBlock> &springs);

    /// Makes the solver of the coarse matrix for its current values.
    void
    update_coarse_solver();

    /// x = the coarse matrix's inverse (or ML's V-cycle for it) applied to b.
    void
    solve_coarse(const Epetra_Vector &b, Epetra_Vector &x) const;

    /// coarse matrix += P^T B P for the block B (B itself on one level).
    void
    add_coarse_spring(const NodalBlock &block);

    /// dst = (K + S) src.
    void
    apply_matrix(Vector &dst, const Vector &src) const;

    /// residual = b - (K + S) x (scratch is overwritten).
    void
    residual_of(const Vector &x, const Vector &b) const;

    /// x += Chebyshev polynomial of the Jacobi-scaled K + S applied to r,
    /// from a zero correction; r is overwritten.
    void
    smooth(Vector &x, Vector &r) const;

    const TrilinosWrappers::SparseMatrix *K = nullptr;
    /// K in nodal blocks, for the fine level's products; null where K's
    /// dofs are not grouped by node.
    std::unique_ptr<NodalBlockMatrix>     fine_blocks;
    unsigned int                          degree = 2;
    double                                lambda_max = 0;

    std::unique_ptr<Epetra_CrsMatrix>   prolongator;
    std::unique_ptr<Epetra_CrsMatrix>   galerkin_matrix;
    std::unique_ptr<Epetra_FECrsMatrix> coarse_matrix;
    std::unique_ptr<Epetra_MultiVector> coarse_null_space;
    unsigned int                        coarse_block_size = 0;
    std::unique_ptr<ML_Epetra::MultiLevelPreconditioner> coarse_solver;
    /// The direct solver (Amesos) of a coarse matrix that ML would only
    /// factor, with its problem; null otherwise.
    std::unique_ptr<Epetra_LinearProblem> direct_problem;
    std::unique_ptr<Amesos_BaseSolver>    direct_solver;
    Teuchos::ParameterList              coarse_parameters;
    double                              chebyshev_ratio = 20;

    /// The springs as (local row, local column, value) of the fine matrix.
    std::vector<int>    spring_rows, spring_columns;
    std::vector<double> spring_values;

    Vector diagonal_of_K;
    Vector inverse_diagonal;
    mutable Vector residual, direction, scratch;
    mutable std::unique_ptr<Epetra_Vector> coarse_residual, coarse_correction;
  };
} // namespace FrictionalContact
