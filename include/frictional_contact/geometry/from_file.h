#pragma once

#include <frictional_contact/geometry/interface.h>

#include <string>

namespace FrictionalContact
{
  namespace Geometry
  {
    /**
     * A coarse mesh read from a file by deal.II's GridIn (Gmsh .msh, UCD,
     * VTK, Abaqus, ... by extension), with the physical tags of the boundary
     * faces as boundary ids and Gmsh's physical names as boundary names.
     * Optionally one curved boundary (a sphere or a cylinder) stays round
     * under refinement. Owns the names and that manifold's description.
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

    private:
      std::string                               file_name;
      std::map<std::string, types::boundary_id> names;
      std::string                               curved_boundaries;
      std::string                               curved_shape;
      Point<dim>                                curved_center;
      Tensor<1, dim>                            curved_axis;
    };
  } // namespace Geometry
} // namespace FrictionalContact
