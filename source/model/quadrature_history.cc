#include <deal.II/base/geometry_info.h>

#include <frictional_contact/model/quadrature_history.h>

#include <cstring>
#include <limits>
#include <utility>

namespace FrictionalContact
{
  namespace
  {
    std::vector<char>
    to_bytes(const std::vector<double> &values)
    {
      std::vector<char> bytes(values.size() * sizeof(double));
      if (!values.empty())
        std::memcpy(bytes.data(), values.data(), bytes.size());
      return bytes;
    }
  } // namespace



  template <int dim>
  QuadratureHistory<dim>::QuadratureHistory(const Materials<dim>  &materials,
                                            const Quadrature<dim> &quadrature)
    : materials(materials)
    , quadrature(quadrature)
  {
    // Children of a hypercube are numbered like its vertices: child c lies
    // at the corner of vertex c.
    const unsigned int n_children = GeometryInfo<dim>::max_children_per_cell;
    std::vector<Point<dim>> child_centre(n_children);
    for (unsigned int c = 0; c < n_children; ++c)
      child_centre[c] =
        Point<dim>() + 0.5 * GeometryInfo<dim>::unit_cell_vertex(c) +
        0.25 * (Point<dim>() + GeometryInfo<dim>::unit_cell_vertex(n_children - 1));
    const auto nearest = [](const Point<dim> &x, const auto &candidates) {
      unsigned int best = 0;
      for (unsigned int k = 1; k < candidates.size(); ++k)
        if (x.distance(candidates[k]) < x.distance(candidates[best]))
          best = k;
      return best;
    };
    for (unsigned int c = 0; c < n_children; ++c)
      parent_point_of_child.push_back(nearest(child_centre[c], quadrature.get_points()));
    for (const Point<dim> &x : quadrature.get_points())
      child_of_parent_point.push_back(nearest(x, child_centre));
  }



  template <int dim>
  void
  QuadratureHistory<dim>::reset(const parallel::distributed::Triangulation<dim> &mesh)
  {
    storage.clear();
    stored_values = 0;
    if (!active())
      return;
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          storage.template initialize<CellValues>(cell, 1);
          storage.get_data(cell)[0]->values.assign(n_values(cell->material_id()), 0.);
          stored_values += n_values(cell->material_id());
        }
  }



  template <int dim>
  double *
  QuadratureHistory<dim>::values(const CellIterator &cell)
  {
    return const_cast<double *>(std::as_const(*this).values(cell));
  }



  template <int dim>
  const double *
  QuadratureHistory<dim>::values(const CellIterator &cell) const
  {
    // A law without history has nothing stored (and the lookup, by the
    // cell's id, is what costs).
    if (n_values(cell->material_id()) == 0)
      return nullptr;
    const auto data = storage.try_get_data(cell);
    if (!data || (*data)[0]->values.empty())
      return nullptr;
    return (*data)[0]->values.data();
  }



  template <int dim>
  std::vector<char>
  QuadratureHistory<dim>::pack(
    const CellIterator                                                    &cell,
    const typename parallel::distributed::Triangulation<dim>::CellStatus status) const
  {
    using Tria = parallel::distributed::Triangulation<dim>;
    const unsigned int n_points = quadrature.size();
    if (status != Tria::CELL_COARSEN)
      {
        const double *own = values(cell);
        return own == nullptr ?
                 std::vector<char>() :
                 to_bytes({own, own + n_values(cell->material_id())});
      }
    const unsigned int  n = n_values(cell->material_id()) / n_points;
    std::vector<double> averaged(n * n_points, 0.);
    for (unsigned int q = 0; q < n_points && n > 0; ++q)
      {
        const double *child = values(cell->child(child_of_parent_point[q]));
        for (unsigned int p = 0; p < n_points; ++p)
          for (unsigned int k = 0; k < n; ++k)
            averaged[q * n + k] += child[p * n + k] / n_points;
      }
    return to_bytes(averaged);
  }



  template <int dim>
  void
  QuadratureHistory<dim>::attach(parallel::distributed::Triangulation<dim> &mesh)
  {
    if (!active())
      return;
    handle = mesh.register_data_attach(
      [this](const CellIterator &cell, const auto status) { return pack(cell, status); },
      /*returns_variable_size_data=*/true);
  }



  template <int dim>
  void
  QuadratureHistory<dim>::unpack(parallel::distributed::Triangulation<dim> &mesh)
  {
    if (!active())
      return;
    // After load() nothing was attached in this run: attach as the saving
    // run did, so that the handle is the one its data was stored under.
    if (handle == numbers::invalid_unsigned_int)
      attach(mesh);
    using Tria = parallel::distributed::Triangulation<dim>;
    const unsigned int n_points = quadrature.size();
    std::map<CellId, std::vector<double>> received;
    mesh.notify_ready_to_unpack(
      handle,
      [&](const CellIterator                                        &cell,
          const typename Tria::CellStatus                            status,
          const boost::iterator_range<std::vector<char>::const_iterator> &bytes) {
        std::vector<double> data(bytes.size() / sizeof(double));
        if (!data.empty())
          std::memcpy(data.data(), &*bytes.begin(), bytes.size());
        if (status != Tria::CELL_REFINE)
          {
            received[cell->id()] = std::move(data);
            return;
          }
        const unsigned int n = data.size() / n_points;
        for (unsigned int c = 0; c < cell->n_children(); ++c)
          {
            std::vector<double> &child = received[cell->child(c)->id()];
            child.resize(data.size());
            for (unsigned int p = 0; p < n_points; ++p)
              std::copy_n(data.begin() + parent_point_of_child[c] * n, n,
                          child.begin() + p * n);
          }
      });
    handle = numbers::invalid_unsigned_int;
    storage.clear();
    stored_values = 0;
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          storage.template initialize<CellValues>(cell, 1);
          std::vector<double> &values = storage.get_data(cell)[0]->values;
          const auto           it     = received.find(cell->id());
          values = it != received.end() ? std::move(it->second) : std::vector<double>();
          values.resize(n_values(cell->material_id()), 0.);
          stored_values += values.size();
        }
  }



  template <int dim>
  std::size_t
  QuadratureHistory<dim>::size_in_bytes() const
  {
    return stored_values * sizeof(double);
  }

  template class QuadratureHistory<2>;
  template class QuadratureHistory<3>;
} // namespace FrictionalContact
