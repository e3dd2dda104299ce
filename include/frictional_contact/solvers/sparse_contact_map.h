#pragma once

#include <deal.II/base/index_set.h>

#include <frictional_contact/solvers/contact_map.h>

#include <array>
#include <utility>
#include <vector>

namespace FrictionalContact
{
  /**
   * A general sparse T, as an FCLIB file gives it: candidate j has dim
   * columns (normal first), each a list of (row, value) pairs, and the
   * columns of different candidates may share rows (several contacts on
   * one rigid body, say). Owns the columns of this rank's candidates, with
   * rows given as global indices of locally owned entries.
   */
  template <int dim>
  class SparseContactMap : public ContactMap<dim>
  {
  public:
    using Column = std::vector<std::pair<types::global_dof_index, double>>;
    using Vector = typename ContactMap<dim>::Vector;

    /**
     * @p columns holds dim columns per local candidate; @p owned_rows the
     * locally owned rows of the vectors T acts on (every row of a column
     * must be one of them).
     */
    SparseContactMap(std::vector<std::array<Column, dim>> columns,
                     const double                         friction_coefficient,
                     const IndexSet                      &owned_rows,
                     const MPI_Comm                       comm);

    unsigned int
    n_local() const override
    {
      return columns.size();
    }

    types::global_dof_index
    n_candidates() const override
    {
      return n_global;
    }

    Tensor<1, dim>
    local_part(const unsigned int j, const Vector &u) const override;

    void
    apply(const std::vector<Tensor<1, dim>> &r, Vector &f) const override;

    void
    add_reaction(const unsigned int    j,
                 const Tensor<1, dim> &r_j,
                 Vector               &f) const override;

    std::vector<double>
    normal_stiffness(const StiffnessOperator &K) const override;

    /// By the power iteration on T^T T, to a relative change of 1e-12.
    double
    largest_singular_value() const override;

    /// One coefficient for all contacts (FCLIB files with several are
    /// refused when read).
    const FrictionCone<dim> &
    friction_cone(const unsigned int) const override
    {
      return cone;
    }

    double
    largest_friction_coefficient() const override
    {
      return cone.mu;
    }

  private:
    /// Columns with rows as indices into the locally owned range.
    std::vector<std::array<std::vector<std::pair<unsigned int, double>>, dim>>
                            columns;
    FrictionCone<dim>       cone;
    IndexSet                owned_rows;
    MPI_Comm                mpi_communicator;
    types::global_dof_index n_global;
  };
} // namespace FrictionalContact
