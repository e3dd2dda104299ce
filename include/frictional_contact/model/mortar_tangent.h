#pragma once

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <frictional_contact/solvers/stiffness_operator.h>

namespace FrictionalContact
{
  /// @p result = Q^T A Q for the basis @p basis (Q) of contact pairs.
  void
  transform_to_basis(const TrilinosWrappers::SparseMatrix &basis,
                     const TrilinosWrappers::SparseMatrix &A,
                     TrilinosWrappers::SparseMatrix       &result);

  /**
   * The tangent of nonlinear laws in the basis u = Q w of contact pairs,
   * K_T,w = Q^T K_T Q, as the Newton solves use it: its products are those
   * of Q, K_T and Q^T in turn, so that a Newton step's new tangent (or new
   * Q, where the mortar rows follow the iterates) costs no matrix-matrix
   * product. Its entries (diagonal, node blocks, the matrix) are those of
   * the explicit product, made on request at an increment's start, where
   * the solvers' set-up reads them; asked for after the tangent changed
   * without them, it throws. Where the rows follow the iterates, the
   * products also take the rows' sliding and the slave normals' turn
   * (take_geometry()), which make the operator unsymmetric. Owns that
   * product and two work vectors.
   */
  class MortarTangent : public StiffnessOperator
  {
  public:
    /// The operator of @p basis (Q, kept by reference) and a tangent
    /// given by take().
    explicit MortarTangent(const TrilinosWrappers::SparseMatrix &basis)
      : basis(basis)
    {}

    /// K_T (kept by reference) with Q as it is now; with @p make_entries
    /// also the explicit product (collective).
    void
    take(const TrilinosWrappers::SparseMatrix &tangent, const bool make_entries);

    /// H and F (kept by reference; null: none), added to the products as
    /// H^T + F Q: the master share of the reactions as the mortar rows
    /// slide, and the slave nodes' turning frames (MortarBasis::
    /// follow_reactions()). Not in the entries.
    void
    take_geometry(const TrilinosWrappers::SparseMatrix *sliding_rows,
                  const TrilinosWrappers::SparseMatrix *turning_frames)
    {
      sliding = sliding_rows;
      turning = turning_frames;
    }

    bool
    is_symmetric() const override
    {
      return sliding == nullptr && turning == nullptr;
    }

    void
    vmult(Vector &dst, const Vector &src) const override;

    double
    diag_element(const types::global_dof_index i) const override;

    std::vector<FullMatrix<double>>
    blocks(const std::vector<std::vector<types::global_dof_index>> &nodes) const override;

    IndexSet
    locally_owned_domain_indices() const override
    {
      return basis.locally_owned_domain_indices();
    }

    MPI_Comm
    get_mpi_communicator() const override
    {
      return basis.get_mpi_communicator();
    }

    bool
    is_assembled() const override
    {
      return true;
    }

    const TrilinosWrappers::SparseMatrix &
    matrix(const std::string &purpose) const override;

  private:
    /// The explicit product, or an internal error naming @p what where
    /// the tangent changed since it was made.
    const TrilinosWrappers::SparseMatrix &
    entries(const std::string &what) const;

    const TrilinosWrappers::SparseMatrix &basis;
    const TrilinosWrappers::SparseMatrix *tangent = nullptr;
    const TrilinosWrappers::SparseMatrix *sliding = nullptr;
    const TrilinosWrappers::SparseMatrix *turning = nullptr;
    TrilinosWrappers::SparseMatrix        product;
    bool                                  entries_current = false;
    /// Q src and K_T Q src.
    mutable Vector in_u, force_in_u;
  };
} // namespace FrictionalContact
