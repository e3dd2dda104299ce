#pragma once

#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_dgq.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <frictional_contact/material/material.h>
#include <frictional_contact/solvers/volumetric_split.h>

#include <array>
#include <vector>

namespace FrictionalContact
{
  /**
   * The matrices of the VolumetricSplit of a B-bar body's stiffness,
   * assembled cell by cell beside K: A (K with the bulk modulus of
   * nu = 0.4), B (the cell integrals of div, one row per cell, numbered by
   * a piecewise-constant element) and the diagonals of C and of the
   * approximate Schur complement. Made only when a body's material uses the
   * B-bar element with a bulk modulus above that of nu = 0.4 (the cells of
   * the other bodies get a zero row of B and a pressure that stays zero);
   * owns the matrices, the cell numbering and the vectors.
   */
  template <int dim>
  class VolumetricBlocks
  {
  public:
    explicit VolumetricBlocks(const Materials<dim> &materials);

    /// Whether some body's material makes a split at all.
    bool
    active() const
    {
      return any_penalty;
    }

    /// Numbers the cells, makes the sparsity of A (that of K, given) and of B.
    void
    setup(const DoFHandler<dim>                &dof_handler,
          const AffineConstraints<double>      &constraints,
          const TrilinosWrappers::SparseMatrix &stiffness);

    /// Zeroes the matrices and vectors before an assembly.
    void
    start_assembly();

    /**
     * Adds a cell: @p cell_stiffness is its block of K (with the full bulk
     * modulus), @p divergence_integral the integrals of div phi_i and
     * @p volume its volume.
     */
    void
    add_cell(const typename DoFHandler<dim>::active_cell_iterator &cell,
             const FullMatrix<double>                            &cell_stiffness,
             const std::vector<double> &divergence_integral,
             const double               volume,
             const std::vector<types::global_dof_index> &dof_indices,
             const AffineConstraints<double>            &constraints);

    /// Compresses; gives A the constrained diagonal entries of the
    /// assembled K (@p stiffness).
    void
    finish_assembly(const TrilinosWrappers::SparseMatrix &stiffness,
                    const AffineConstraints<double>      &constraints);

    /// The split, for the solvers (empty unless active()).
    VolumetricSplit
    split() const;

    /**
     * Lame's lambda and mu of A on the cells of @p material if the split
     * takes their volumetric part (kappa_0 - 2 G / dim and G: the bulk
     * modulus of nu = 0.4, which A has as a mean dilatation, here as at
     * Gauss points, as the geometric multigrid's operators take it);
     * @p of_stiffness (K's) otherwise.
     */
    static std::array<double, 2>
    reduced_lame_parameters(const ElasticConstants<dim> &material,
                            const std::array<double, 2>      &of_stiffness);

  private:
    const Materials<dim> &materials;
    bool                  any_penalty = false;

    FE_DGQ<dim>                    cell_fe;
    DoFHandler<dim>                cell_numbering;
    AffineConstraints<double>      no_constraints;
    TrilinosWrappers::SparseMatrix reduced_stiffness;
    TrilinosWrappers::SparseMatrix divergence;
    TrilinosWrappers::MPI::Vector  compliance;
    TrilinosWrappers::MPI::Vector  inverse_schur;
    TrilinosWrappers::MPI::Vector  row_weight;
    double                         stiffness_bound = 0;
    FullMatrix<double>             cell_matrix;
    FullMatrix<double>             cell_row;
  };
} // namespace FrictionalContact
