#pragma once

#include <deal.II/grid/tria.h>

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
    /**
     * The mesh of the half ball (or disc) of @p radius about @p center, cut
     * by @p n_symmetry_planes, with its boundary ids (curved 0, top 1,
     * x symmetry 2, y symmetry 3) and manifold ids (0 on the curved face,
     * 1 inside), for a geometry to place in its coarse mesh.
     */
    template <int dim>
    void
    half_ball_mesh(Triangulation<dim> &mesh,
                   const Point<dim>   &center,
                   const double        radius,
                   const unsigned int  n_symmetry_planes);

    /// The manifolds of half_ball_mesh() on the distributed mesh that
    /// holds it (after its coarse mesh is made).
    template <int dim>
    void
    attach_half_ball_manifolds(parallel::distributed::Triangulation<dim> &triangulation,
                               const Point<dim>                          &center);

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
