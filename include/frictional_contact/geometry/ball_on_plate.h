#pragma once

#include <frictional_contact/geometry/interface.h>

namespace FrictionalContact
{
  namespace Geometry
  {
    /**
     * Two bodies: the lower half of a ball (a disc in 2D) resting on a
     * plate, for Hertz's contact of two elastic bodies. The ball of radius
     * R is the half ball of HalfBall (with its manifolds and symmetry
     * planes), its lowest point at the origin plus a gap; the plate is a
     * box below the plane through the origin (y = 0 in 2D, z = 0 in 3D),
     * cut by the same symmetry planes. Bodies: plate (material id 0), ball
     * (1). Boundaries: ball curved, ball top, ball x symmetry (ball y
     * symmetry), plate left, plate right, plate bottom, plate top (plate
     * front, plate back in 3D); with symmetry planes the plate's left
     * (front) face lies on them.
     */
    template <int dim>
    class BallOnPlate : public Interface<dim>
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
      body_names() const override
      {
        return {{"plate", 0}, {"ball", 1}};
      }

    private:
      double       radius            = 1;
      double       gap               = 0;
      unsigned int n_symmetry_planes = 0;
      /// The plate's half width (or width with a symmetry plane) and
      /// thickness, and its cells.
      double                    plate_width     = 2;
      double                    plate_thickness = 1;
      std::vector<unsigned int> plate_cells;
    };
  } // namespace Geometry
} // namespace FrictionalContact
