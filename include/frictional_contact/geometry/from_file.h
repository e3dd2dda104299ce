#pragma once

#include <deal.II/grid/tria_description.h>

#include <frictional_contact/geometry/interface.h>

#include <string>
#include <vector>

namespace FrictionalContact
{
  namespace Geometry
  {
    /**
     * A coarse mesh read from a file by deal.II's GridIn (Gmsh .msh, UCD,
     * VTK, Abaqus, ... by extension), with the physical tags of the boundary
     * faces as boundary ids and Gmsh's physical names as boundary names.
     * The named physical groups of cells (surfaces in 2D, volumes in 3D)
     * are bodies: several make a scene of several bodies, which must not
     * share vertices unless asked to split them (each body then gets its
     * own copy, and the faces between two bodies a and b become the
     * boundaries 'a on b' and 'b on a'). Optionally one curved boundary (a
     * sphere or a cylinder) stays round under refinement. Owns the names,
     * the coarse mesh as read (and split) and that manifold's description.
     */
    template <int dim>
    class FromFile : public Interface<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      void
      create_coarse_mesh(
        parallel::distributed::Triangulation<dim> &triangulation) const override;

      std::map<std::string, types::boundary_id>
      boundary_names() const override;

      std::map<std::string, types::material_id>
      body_names() const override;

    private:
      /// Reads the file into the coarse mesh description; checks the
      /// bodies, and splits them or refuses if they share vertices.
      void
      read_mesh();

      std::string                               file_name;
      std::map<std::string, types::boundary_id> names;
      std::map<std::string, types::material_id> bodies;
      bool                                      split_bodies = false;
      /// The coarse mesh: vertices, cells (with their body's material
      /// id) and boundary faces (with their ids).
      std::vector<Point<dim>>                   vertices;
      std::vector<CellData<dim>>                cells;
      SubCellData                               faces;
      std::string                               curved_boundaries;
      std::string                               curved_shape;
      Point<dim>                                curved_center;
      Tensor<1, dim>                            curved_axis;
    };
  } // namespace Geometry
} // namespace FrictionalContact
