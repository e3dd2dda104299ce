#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <algorithm>
#include <array>
#include <map>
#include <utility>
#include <vector>

namespace FrictionalContact
{
  using namespace dealii;

  template <int dim>
  class ContactOperator;

  /// Entries of a matrix by (row, column), summed.
  using Couplings =
    std::map<std::pair<types::global_dof_index, types::global_dof_index>, double>;

  /**
   * A Trilinos matrix of Couplings (rows: the locally owned dofs), made
   * again as they change: where every rank's pattern already holds the
   * new entries, their values are set in it, and the positions without an
   * entry now to zero (or the identity's one), instead of a new pattern
   * being made; a new pattern keeps the old positions too. The geometry's
   * matrices of a pair whose rows follow the Newton iterates so keep their
   * pattern while slave nodes move among segments they have touched. Owns
   * the matrix and its positions.
   */
  class CouplingMatrix
  {
  public:
    /// The matrix of @p entries, plus the identity with @p identity (an
    /// entry on the diagonal then replaces its one). Collective.
    void
    take(const IndexSet  &owned,
         const MPI_Comm   comm,
         const Couplings &entries,
         const bool       identity);

    TrilinosWrappers::SparseMatrix matrix;

  private:
    std::vector<Couplings::key_type> positions;
  };

  /**
   * The matrices that the pairs of two bodies give MortarBasis, read off
   * the contact operator's slave nodes on this rank (their mortar rows,
   * the rows' slides and the normals' derivatives): the basis u = Q w and
   * the Newton tangent's terms of the moving geometry. Rows are the free
   * components of the slave nodes; a hanging master dof is replaced by
   * the dofs it hangs from and a held one left out.
   */
  template <int dim>
  class PairCouplings
  {
  public:
    explicit PairCouplings(const ContactOperator<dim> &contact)
      : contact(contact)
    {}

    /// (slave dof, master unknown) -> P_jl for every unknown a slave
    /// node's mortar row reaches: u_S = w_S + sum_l P_jl u_l.
    Couplings
    basis() const;

    /**
     * The change of the master share sum_j P_jl f_j of the reactions
     * @p forces (Cartesian, one per node) as the slave nodes slide: s_a f_b
     * for the slave's free component a and the master's component b, with
     * dP_jl = s . delta (MortarInterface::SlaveNode::master_slides).
     */
    Couplings
    sliding(const std::vector<Tensor<1, dim>> &forces) const;

    /**
     * How the slave nodes' frames turn with the slave surface (where the
     * rows follow the iterates: MortarInterface::SlaveNode::
     * normal_derivatives; empty elsewhere): (slave dof, dof of a vertex
     * that turns its normal) -> entry. Without @p forces, the turn of what
     * the node touches (as ContactMap::normal_turns()); with them, the
     * force of the turning frame (none where a node has no force).
     */
    Couplings
    turns(const std::vector<Tensor<1, dim>> *forces) const;

  private:
    /// The turn of what slave node j touches per move of each vertex of
    /// its slave faces.
    std::vector<std::pair<std::array<types::global_dof_index, dim>, Tensor<2, dim>>>
    turns_per_move(const unsigned int j) const;

    const ContactOperator<dim> &contact;
  };
} // namespace FrictionalContact
