#pragma once

#include <deal.II/base/table.h>
#include <deal.II/base/vectorization.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/matrix_free/fe_evaluation.h>
#include <deal.II/matrix_free/matrix_free.h>
#include <deal.II/matrix_free/operators.h>

#include <array>
#include <cstring>
#include <type_traits>
#include <map>
#include <vector>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * Copies the locally owned entries of @p src into @p dst: a Trilinos
   * vector and deal.II's distributed vector of the matrix-free objects
   * number the locally owned dofs alike, so it is one memcpy.
   */
  template <typename Source, typename Destination>
  void
  copy_owned_entries(const Source &src, Destination &dst)
  {
    static_assert(std::is_same_v<typename Source::value_type, double> &&
                  std::is_same_v<typename Destination::value_type, double>);
    std::memcpy(dst.begin(), src.begin(), src.locally_owned_size() * sizeof(double));
  }

  /// Lame's lambda and the shear modulus of each body (material id): the
  /// isotropic stress sigma = lambda tr(eps) I + 2 mu eps (in 2D lambda is
  /// the plane-stress or plane-strain one).
  using LameParameters = std::map<types::material_id, std::array<double, 2>>;

  /**
   * The stiffness K of linear elasticity on vector-valued Q1 elements
   * without assembling it (deal.II's MatrixFree and FEEvaluation, as in
   * step-37): for each batch of cells the symmetric gradient at the 2^dim
   * Gauss points, the stress, and the integral against the test functions.
   * Constraints (hanging nodes, held boundary components) are those of the
   * MatrixFree object; MatrixFreeOperators::Base makes the constrained rows
   * the identity. Works on the active mesh or on one level of the mesh
   * hierarchy (for geometric multigrid, in float there), optionally with
   * springs on single nodes (the node conditions of a Newton system).
   * Owns the Lame parameters of each cell batch and the springs.
   */
  template <int dim, typename number>
  class ElasticityOperator
    : public MatrixFreeOperators::Base<dim, LinearAlgebra::distributed::Vector<number>>
  {
  public:
    using VectorType = LinearAlgebra::distributed::Vector<number>;

    /// Reads each cell's material id and takes its Lame parameters from
    /// @p lame (after initialize()).
    void
    set_materials(const LameParameters &lame);

    /// A symmetric block on locally owned entries of the vector (their
    /// local indices), row-major.
    struct Spring
    {
      std::vector<unsigned int> rows;
      std::vector<number>       values;
    };

    /// The operator is K + the sum of @p springs from now on (its diagonal
    /// too, at the next compute_diagonal()).
    void
    set_springs(std::vector<Spring> springs);

    void
    clear() override;

    void
    compute_diagonal() override;

    /// K's diagonal without springs (after compute_diagonal()); zero at
    /// constrained dofs.
    const VectorType &
    get_stiffness_diagonal() const
    {
      return stiffness_diagonal;
    }

    /// On the cell batch @p phi is at, with its dof values set: evaluates
    /// the gradients and integrates the stress against the test functions
    /// (the cell's K times the values, into the values).
    void
    integrate_stiffness(FEEvaluation<dim, 1, 2, dim, number> &phi) const;

    /**
     * The matrix of each cell of cell batch @p batch (one per filled lane,
     * without constraints), its dofs numbered as FEEvaluation's: component
     * by component, the vertices in lexicographic order (deal.II's vertex
     * order for Q1).
     */
    std::vector<FullMatrix<double>>
    cell_matrices(const unsigned int batch) const;

  private:
    void
    apply_add(VectorType &dst, const VectorType &src) const override;

    void
    local_apply(const MatrixFree<dim, number>               &data,
                VectorType                                  &dst,
                const VectorType                            &src,
                const std::pair<unsigned int, unsigned int> &cell_range) const;

    /// lambda and 2 mu of each cell batch (lane by lane).
    Table<2, VectorizedArray<number>> moduli;
    std::vector<Spring>               springs;
    /// The diagonal of K (without springs), computed on first use.
    VectorType                        stiffness_diagonal;
  };
} // namespace FrictionalContact
