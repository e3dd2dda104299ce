#include <deal.II/grid/grid_tools.h>

#include <frictional_contact/geometry/mesh_parts.h>

namespace FrictionalContact
{
  namespace Geometry
  {
    template <int dim>
    void
    create_from_parts(Triangulation<dim>                            &triangulation,
                      const std::vector<const Triangulation<dim> *> &parts)
    {
      std::vector<Point<dim>>    vertices;
      std::vector<CellData<dim>> cells;
      SubCellData                faces;
      for (const Triangulation<dim> *part : parts)
        {
          auto [part_vertices, part_cells, part_faces] =
            GridTools::get_coarse_mesh_description(*part);
          const unsigned int offset = vertices.size();
          vertices.insert(vertices.end(), part_vertices.begin(), part_vertices.end());
          const auto append = [offset](auto &from, auto &to) {
            for (auto &item : from)
              {
                for (unsigned int &v : item.vertices)
                  v += offset;
                to.push_back(item);
              }
          };
          append(part_cells, cells);
          append(part_faces.boundary_lines, faces.boundary_lines);
          append(part_faces.boundary_quads, faces.boundary_quads);
        }
      triangulation.create_triangulation(vertices, cells, faces);
    }



    template void
    create_from_parts(Triangulation<2> &, const std::vector<const Triangulation<2> *> &);
    template void
    create_from_parts(Triangulation<3> &, const std::vector<const Triangulation<3> *> &);
  } // namespace Geometry
} // namespace FrictionalContact
