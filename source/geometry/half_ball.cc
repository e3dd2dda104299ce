#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include <frictional_contact/geometry/half_ball.h>
#include <frictional_contact/base/plugins.h>

namespace FrictionalContact
{
  namespace Geometry
  {
    namespace HalfBallFaces
    {
      enum Boundary : types::boundary_id
      {
        curved     = 0,
        top        = 1,
        x_symmetry = 2,
        y_symmetry = 3
      };
      constexpr types::manifold_id sphere_manifold = 0, interior_manifold = 1;
    } // namespace HalfBallFaces

    namespace
    {
      using namespace HalfBallFaces;

      /**
       * The mesh of the part of the unit ball centred at the origin:
       * vertical axis (y in 2D, z in 3D) <= 0, and x >= 0 (and y >= 0)
       * for one (two) symmetry planes; made from deal.II's half and quarter
       * balls by rotations (reflections would turn the cells inside out).
       */
      template <int dim>
      void
      unit_half_ball(Triangulation<dim> &mesh, const unsigned int n_planes)
      {
        if constexpr (dim == 2)
          {
            // half_hyper_ball: x >= 0; quarter_hyper_ball: x, y >= 0.
            // Turned by -90 degrees, (x, y) -> (y, -x).
            if (n_planes == 0)
              GridGenerator::half_hyper_ball(mesh, Point<2>(), 1.);
            else
              GridGenerator::quarter_hyper_ball(mesh, Point<2>(), 1.);
            GridTools::transform([](const Point<2> &p) { return Point<2>(p[1], -p[0]); },
                                 mesh);
          }
        else
          {
            if (n_planes == 0)
              {
                // half_hyper_ball: x >= 0, turned about y: (x, y, z) -> (z, y, -x).
                GridGenerator::half_hyper_ball(mesh, Point<3>(), 1.);
                GridTools::transform(
                  [](const Point<3> &p) { return Point<3>(p[2], p[1], -p[0]); },
                  mesh);
              }
            else
              {
                // The octant x, y, z >= 0 turned about x onto (+, +, -),
                // and, for one plane, also onto (+, -, -).
                // (The pieces take the mesh's smoothing: copies keep it.)
                Triangulation<3> octant(mesh.get_mesh_smoothing());
                GridGenerator::quarter_hyper_ball(octant, Point<3>(), 1.);
                Triangulation<3> front(mesh.get_mesh_smoothing());
                front.copy_triangulation(octant);
                GridTools::transform(
                  [](const Point<3> &p) { return Point<3>(p[0], p[2], -p[1]); },
                  front);
                if (n_planes == 2)
                  mesh.copy_triangulation(front);
                else
                  {
                    Triangulation<3> back(mesh.get_mesh_smoothing());
                    back.copy_triangulation(octant);
                    GridTools::transform(
                      [](const Point<3> &p) { return Point<3>(p[0], -p[1], -p[2]); },
                      back);
                    GridGenerator::merge_triangulations(front, back, mesh, 1e-10);
                  }
              }
          }
      }
    } // namespace



    template <int dim>
    void
    HalfBall<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Center",
                        dim == 2 ? "0, 1" : "0, 0, 1",
                        Patterns::Anything(),
                        "Centre of the disc or ball (length); the flat top "
                        "face goes through it.");
      prm.declare_entry("Radius",
                        "1",
                        Patterns::Double(0.),
                        "Radius (length, > 0).");
      prm.declare_entry("Symmetry planes",
                        "0",
                        Patterns::Integer(0, 2),
                        "0: the whole lower half; 1: only x >= centre (hold "
                        "the boundary 'x symmetry' in x); 2 (3D): only x, y "
                        ">= centre (also 'y symmetry' in y).");
    }



    template <int dim>
    void
    HalfBall<dim>::parse_parameters(ParameterHandler &prm)
    {
      center = Point<dim>(
        Input::parse_vector<dim>("Geometry/Half ball/Center", prm.get("Center")));
      radius = prm.get_double("Radius");
      if (!(radius > 0))
        Input::fail("Geometry/Half ball/Radius",
                    prm.get("Radius"),
                    "the radius must be positive");
      n_symmetry_planes = prm.get_integer("Symmetry planes");
      if (n_symmetry_planes > dim - 1)
        Input::fail("Geometry/Half ball/Symmetry planes",
                    prm.get("Symmetry planes"),
                    "a 2D half disc has at most 1 symmetry plane");
    }



    template <int dim>
    void
    half_ball_mesh(Triangulation<dim> &mesh,
                   const Point<dim>   &center,
                   const double        radius,
                   const unsigned int  n_symmetry_planes)
    {
      using namespace HalfBallFaces;
      unit_half_ball(mesh, n_symmetry_planes);
      mesh.reset_all_manifolds();
      mesh.set_all_manifold_ids(interior_manifold);

      // Name the faces by where they lie; flat faces first, so that the
      // edges they share with the curved face end up round.
      const auto on_plane = [](const auto &face, const unsigned int axis) {
        for (const unsigned int v : face->vertex_indices())
          if (std::abs(face->vertex(v)[axis]) > 1e-10)
            return false;
        return true;
      };
      std::vector<typename Triangulation<dim>::face_iterator> curved_faces;
      for (const auto &cell : mesh.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              if (on_plane(face, dim - 1))
                face->set_boundary_id(top);
              else if (on_plane(face, 0))
                face->set_boundary_id(x_symmetry);
              else if (dim == 3 && on_plane(face, 1))
                face->set_boundary_id(y_symmetry);
              else
                {
                  face->set_boundary_id(curved);
                  curved_faces.push_back(face);
                  continue;
                }
              face->set_all_manifold_ids(numbers::flat_manifold_id);
            }
      for (const auto &face : curved_faces)
        face->set_all_manifold_ids(sphere_manifold);

      GridTools::scale(radius, mesh);
      GridTools::shift(center, mesh);
    }



    template <int dim>
    void
    attach_half_ball_manifolds(parallel::distributed::Triangulation<dim> &triangulation,
                               const Point<dim>                          &center)
    {
      using namespace HalfBallFaces;
      triangulation.set_manifold(sphere_manifold, SphericalManifold<dim>(center));
      TransfiniteInterpolationManifold<dim> interior;
      interior.initialize(triangulation);
      triangulation.set_manifold(interior_manifold, interior);
    }



    template <int dim>
    void
    HalfBall<dim>::create_coarse_mesh(
      parallel::distributed::Triangulation<dim> &triangulation) const
    {
      // The mesh's smoothing (with geometric multigrid: one level between
      // neighbours at a vertex) survives the copy below.
      Triangulation<dim> mesh(triangulation.get_mesh_smoothing());
      half_ball_mesh(mesh, center, radius, n_symmetry_planes);
      triangulation.copy_triangulation(mesh);
      attach_half_ball_manifolds(triangulation, center);
    }



    template void
    half_ball_mesh(Triangulation<2> &, const Point<2> &, const double, const unsigned int);
    template void
    half_ball_mesh(Triangulation<3> &, const Point<3> &, const double, const unsigned int);
    template void
    attach_half_ball_manifolds(parallel::distributed::Triangulation<2> &, const Point<2> &);
    template void
    attach_half_ball_manifolds(parallel::distributed::Triangulation<3> &, const Point<3> &);



    template <int dim>
    std::map<std::string, types::boundary_id>
    HalfBall<dim>::boundary_names() const
    {
      using namespace HalfBallFaces;
      std::map<std::string, types::boundary_id> names = {{"curved", curved},
                                                         {"top", top}};
      if (n_symmetry_planes >= 1)
        names["x symmetry"] = x_symmetry;
      if (n_symmetry_planes >= 2)
        names["y symmetry"] = y_symmetry;
      return names;
    }

    FRICTIONAL_CONTACT_REGISTER_PLUGIN(
      Interface,
      HalfBall,
      "half ball",
      "The lower half of a disc (2D) or ball (3D), curved face down, "
      "optionally cut by symmetry planes through the centre. Boundaries: "
      "curved, top, x symmetry, y symmetry.")
  } // namespace Geometry
} // namespace FrictionalContact
