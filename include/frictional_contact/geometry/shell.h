#pragma once

#include <frictional_contact/geometry/interface.h>

namespace FrictionalContact
{
  namespace Geometry
  {
    /**
     * A quarter of a thick-walled tube (2D, plane strain: a long cylinder)
     * or an eighth of a thick-walled sphere (3D) between two radii about a
     * centre, cut by the coordinate planes through the centre: Lamé's
     * problems. Owns the spherical manifold that keeps both curved faces
     * round. Boundaries: inner, outer, x symmetry, y symmetry, z symmetry.
     */
    template <int dim>
    class Shell : public Interface<dim>
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
      Point<dim>   center;
      double       inner_radius = 0.5;
      double       outer_radius = 1;
      /// Coarse cells around the quarter (2D; 0: deal.II's choice).
      unsigned int n_cells = 0;
    };
  } // namespace Geometry
} // namespace FrictionalContact
