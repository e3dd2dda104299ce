#include <frictional_contact/model/reference_gradients.h>

namespace FrictionalContact
{
  template <int dim>
  void
  ReferenceGradients<dim>::reinit(
    const DoFHandler<dim> &dof_handler,
    FEValues<dim>         &gauss,
    FEValues<dim>         &lobatto,
    const std::function<bool(const typename DoFHandler<dim>::active_cell_iterator &)>
      &corner_points)
  {
    const unsigned int n_cells = dof_handler.get_triangulation().n_active_cells();
    first_point.assign(n_cells + 1, 0);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        first_point[cell->active_cell_index() + 1] =
          (corner_points(cell) ? lobatto : gauss).n_quadrature_points;
    for (unsigned int c = 0; c < n_cells; ++c)
      first_point[c + 1] += first_point[c];
    weights.resize(first_point.back());
    vertex_gradients.resize(n_vertices * first_point.back());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          FEValues<dim> &fe_values = corner_points(cell) ? lobatto : gauss;
          fe_values.reinit(typename Triangulation<dim>::cell_iterator(cell));
          const std::size_t first = first_point[cell->active_cell_index()];
          copy(fe_values, weights.data() + first, vertex_gradients.data() + n_vertices * first);
        }
  }



  template <int dim>
  void
  ReferenceGradients<dim>::copy(const FEValues<dim> &fe_values,
                                double              *JxW,
                                Tensor<1, dim>      *gradients)
  {
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        JxW[q] = fe_values.JxW(q);
        for (unsigned int a = 0; a < n_vertices; ++a)
          gradients[n_vertices * q + a] = fe_values.shape_grad(a, q);
      }
  }

  template class ReferenceGradients<2>;
  template class ReferenceGradients<3>;
} // namespace FrictionalContact
