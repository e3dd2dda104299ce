#pragma once

#include <deal.II/base/geometry_info.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>

#include <cstddef>
#include <functional>
#include <vector>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * What the cell kernels of a nonlinear body take of FEValues, kept for
   * the whole mesh: at the points of each locally owned cell, in the
   * reference configuration, the weights JxW and the gradients grad N_a of
   * the vertices' Q1 functions. They do not change while the mesh stays
   * (the small-strain kernels and the total Lagrangian ones alike), and
   * FEValues::reinit() took about 1,900 instructions of the 13,500 of a
   * curved 2D cell's force and tangent at every Newton step (callgrind,
   * the O-ring). A flat table by active cell index, not CellDataStorage
   * (a map lookup and an allocation per point): 36 doubles per 2D cell on
   * the Gauss points, 200 per 3D cell. Owns the tables; reinit() takes
   * them anew for a new mesh.
   */
  template <int dim>
  class ReferenceGradients
  {
  public:
    static constexpr unsigned int n_vertices = GeometryInfo<dim>::vertices_per_cell;

    /// Takes the tables of the locally owned cells of @p dof_handler, each
    /// from @p gauss or, where @p corner_points says so for the cell, from
    /// @p lobatto (FEValues of a scalar Q1 element, with gradients and
    /// JxW).
    void
    reinit(const DoFHandler<dim>                                                   &dof_handler,
           FEValues<dim>                                                           &gauss,
           FEValues<dim>                                                           &lobatto,
           const std::function<bool(const typename DoFHandler<dim>::active_cell_iterator &)>
             &corner_points);

    /// Copies the JxW and the gradients of the vertices' functions of the
    /// cell @p fe_values was last reinit() on into @p JxW (one per point)
    /// and @p gradients (entry q n_vertices + a): the tables' layout.
    static void
    copy(const FEValues<dim> &fe_values, double *JxW, Tensor<1, dim> *gradients);

    /// Whether the tables are kept.
    bool
    kept() const
    {
      return !first_point.empty();
    }

    /// The points of the cell of @p active_cell_index (0 for a cell this
    /// rank does not own).
    unsigned int
    n_points(const unsigned int active_cell_index) const
    {
      return first_point[active_cell_index + 1] - first_point[active_cell_index];
    }

    /// JxW at the cell's points.
    const double *
    JxW(const unsigned int active_cell_index) const
    {
      return weights.data() + first_point[active_cell_index];
    }

    /// grad N_a at the cell's point q: entry q n_vertices + a.
    const Tensor<1, dim> *
    gradients(const unsigned int active_cell_index) const
    {
      return vertex_gradients.data() + n_vertices * first_point[active_cell_index];
    }

  private:
    /// Per active cell index, the index of its first point (one more
    /// entry: the end of the last cell).
    std::vector<std::size_t> first_point;
    std::vector<double>      weights;
    std::vector<Tensor<1, dim>> vertex_gradients;
  };
} // namespace FrictionalContact
