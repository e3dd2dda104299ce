#pragma once

#include <frictional_contact/geometry/interface.h>

namespace FrictionalContact
{
  namespace Geometry
  {
    /**
     * The lower half of a disc (2D: y <= centre) or of a ball (3D: z <=
     * centre), curved face down, flat face up: the body of Hertz's and
     * Cattaneo-Mindlin's problems. Symmetry planes through the centre can
     * cut it further: x >= centre (2D and 3D), and y >= centre (3D). Owns
     * the manifolds that keep the curved face round under refinement.
     * Boundaries: curved, top, x symmetry, y symmetry.
     */
    template <int dim>
    class HalfBall : public Interface<dim>
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
      double       radius = 1;
      /// 0: the whole half; 1: x >= centre; 2: x, y >= centre (3D).
      unsigned int n_symmetry_planes = 0;
    };
  } // namespace Geometry
} // namespace FrictionalContact
