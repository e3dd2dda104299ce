#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <string>
#include <vector>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * K as the solvers use it: products with Trilinos vectors, its diagonal
   * and its blocks on the dofs of single nodes. Either the assembled matrix
   * (AssembledStiffness) or the matrix-free operator (MatrixFreeStiffness,
   * <Linear solver/Matrix-free stiffness>); the paths that need the
   * entries themselves (ML, the Cholesky factor, the contact pairs' Q^T K
   * Q, the FCLIB export) ask for matrix(), which says what is missing when
   * K is not assembled.
   */
  class StiffnessOperator
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    virtual ~StiffnessOperator() = default;

    /// dst = K src (vectors of the locally owned dofs).
    virtual void
    vmult(Vector &dst, const Vector &src) const = 0;

    /// K_ii for a locally owned dof i.
    virtual double
    diag_element(const types::global_dof_index i) const = 0;

    /**
     * For each of @p nodes (the dim dofs of a locally owned node, component
     * by component), K on them, dim x dim. The matrix-free operator sums
     * its cells' blocks, which leaves out what hanging nodes add.
     * Collective.
     */
    virtual std::vector<FullMatrix<double>>
    blocks(const std::vector<std::vector<types::global_dof_index>> &nodes) const = 0;

    virtual IndexSet
    locally_owned_domain_indices() const = 0;

    virtual MPI_Comm
    get_mpi_communicator() const = 0;

    virtual bool
    is_assembled() const = 0;

    /// Whether K is symmetric (CG may solve with it where the contact
    /// conditions keep the system so).
    virtual bool
    is_symmetric() const
    {
      return true;
    }

    /// The assembled matrix; throws an InputError naming @p purpose when K
    /// is matrix-free.
    virtual const TrilinosWrappers::SparseMatrix &
    matrix(const std::string &purpose) const = 0;
  };



  /// The assembled K, by reference (it must outlive this object).
  class AssembledStiffness : public StiffnessOperator
  {
  public:
    explicit AssembledStiffness(const TrilinosWrappers::SparseMatrix &K)
      : K(K)
    {}

    void
    vmult(Vector &dst, const Vector &src) const override
    {
      K.vmult(dst, src);
    }

    double
    diag_element(const types::global_dof_index i) const override
    {
      return K.diag_element(i);
    }

    std::vector<FullMatrix<double>>
    blocks(const std::vector<std::vector<types::global_dof_index>> &nodes) const override;

    IndexSet
    locally_owned_domain_indices() const override
    {
      return K.locally_owned_domain_indices();
    }

    MPI_Comm
    get_mpi_communicator() const override
    {
      return K.get_mpi_communicator();
    }

    bool
    is_assembled() const override
    {
      return true;
    }

    const TrilinosWrappers::SparseMatrix &
    matrix(const std::string &) const override
    {
      return K;
    }

  private:
    const TrilinosWrappers::SparseMatrix &K;
  };
} // namespace FrictionalContact
