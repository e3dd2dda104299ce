#pragma once

#include <frictional_contact/geometry/interface.h>

#include <array>

namespace FrictionalContact
{
  namespace Geometry
  {
    /**
     * A rectangle (2D) or brick (3D) of given extents, subdivided into
     * X x Y (x Z) equal cells. Boundaries: left (x = min), right, bottom,
     * top in 2D; left, right, front (y = min), back, bottom (z = min), top
     * in 3D. Kanno's examples I and II are boxes.
     */
    template <int dim>
    class Box : public Interface<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      void
      create_coarse_mesh(
        parallel::distributed::Triangulation<dim> &triangulation) const override;

      unsigned int
      n_built_in_refinements() const override;

      std::map<std::string, types::boundary_id>
      boundary_names() const override;

    private:
      Point<dim>                        origin;
      Point<dim>                        extents;
      std::array<unsigned int, dim>     repetitions;
      /// The coarse mesh has repetitions / 2^n_halvings cells per direction.
      unsigned int                      n_halvings = 0;
    };
  } // namespace Geometry
} // namespace FrictionalContact
