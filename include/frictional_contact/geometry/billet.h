#pragma once

#include <frictional_contact/geometry/interface.h>

namespace FrictionalContact
{
  namespace Geometry
  {
    /**
     * A cylindrical billet for upsetting and forging: in 3D the cylinder
     * of radius R about the z axis from z = 0 to the height H, whole or
     * the quarter x, y >= 0 (two symmetry planes); in 2D the half section
     * [0, R] x [0, H] of a plane-strain strip (x = 0 a symmetry plane).
     * The bottom face is where a die or a mid-plane symmetry holds it, the
     * top face meets the die. With a neck imperfection the radius grows
     * from the bottom face to the top: a bar for a tensile test. Owns the
     * manifolds that keep the side round (and tapered) under refinement. Boundaries: bottom, top, side, x symmetry,
     * y symmetry (3D quarter).
     */
    template <int dim>
    class Billet : public Interface<dim>
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
      double       radius = 1;
      double       height = 1;
      /// Cells along the height, before global refinement.
      unsigned int height_cells = 2;
      /// 3D: whether only the quarter x, y >= 0 is meshed.
      bool         quarter = true;
      /// The radius's relative reduction at the bottom face (a neck's seed).
      double       imperfection = 0;
    };
  } // namespace Geometry
} // namespace FrictionalContact
