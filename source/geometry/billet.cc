#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include <frictional_contact/base/input.h>
#include <frictional_contact/base/plugins.h>
#include <frictional_contact/geometry/billet.h>

#include <cmath>

namespace FrictionalContact
{
  namespace Geometry
  {
    namespace BilletFaces
    {
      enum Boundary : types::boundary_id
      {
        bottom     = 0,
        top        = 1,
        side       = 2,
        x_symmetry = 3,
        y_symmetry = 4
      };
      constexpr types::manifold_id side_manifold = 0, interior_manifold = 1;
    } // namespace BilletFaces



    template <int dim>
    void
    Billet<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Radius",
                        "1",
                        Patterns::Anything(),
                        "R: the billet's radius (3D) or half width (2D) "
                        "(length, > 0).");
      prm.declare_entry("Height",
                        "1",
                        Patterns::Anything(),
                        "H: the height of the meshed billet, from z = 0 (y "
                        "in 2D) up (length, > 0); with a mid-plane symmetry "
                        "at the bottom, half the billet's.");
      prm.declare_entry("Height repetitions",
                        "0",
                        Patterns::Integer(0),
                        "Cells along the height before global refinement; 0: "
                        "cells about as tall as wide (2 across the radius).");
      prm.declare_entry("Symmetry planes",
                        "2",
                        Patterns::Integer(0, 2),
                        "3D: 2, the quarter x, y >= 0 (hold 'x symmetry' in "
                        "x and 'y symmetry' in y), or 0, the whole cylinder. "
                        "2D takes the half section x >= 0 always (hold 'x "
                        "symmetry' in x).");
    }



    template <int dim>
    void
    Billet<dim>::parse_parameters(ParameterHandler &prm)
    {
      for (const char *entry : {"Radius", "Height"})
        {
          const double value = Input::parse_number(std::string("Geometry/Billet/") + entry,
                                                   prm.get(entry),
                                                   "a positive length");
          if (!(value > 0))
            Input::fail(std::string("Geometry/Billet/") + entry, prm.get(entry),
                        "a positive length");
          (std::string(entry) == "Radius" ? radius : height) = value;
        }
      const unsigned int planes = prm.get_integer("Symmetry planes");
      if (dim == 3 && planes == 1)
        Input::fail("Geometry/Billet/Symmetry planes", prm.get("Symmetry planes"),
                    "0 (the whole cylinder) or 2 (the quarter x, y >= 0)");
      quarter      = planes == 2;
      height_cells = prm.get_integer("Height repetitions");
      if (height_cells == 0)
        height_cells = std::max(1, static_cast<int>(std::round(2. * height / radius)));
    }



    template <int dim>
    void
    Billet<dim>::create_coarse_mesh(
      parallel::distributed::Triangulation<dim> &triangulation) const
    {
      using namespace BilletFaces;
      if constexpr (dim == 2)
        {
          GridGenerator::subdivided_hyper_rectangle(triangulation,
                                                    {2u, height_cells},
                                                    Point<2>(),
                                                    Point<2>(radius, height));
          for (const auto &cell : triangulation.active_cell_iterators())
            for (const auto &face : cell->face_iterators())
              if (face->at_boundary())
                {
                  const Point<2> c = face->center();
                  face->set_boundary_id(std::abs(c[1]) < 1e-10 * height          ? bottom :
                                        std::abs(c[1] - height) < 1e-10 * height ? top :
                                        std::abs(c[0]) < 1e-10 * radius          ? x_symmetry :
                                                                                   side);
                }
        }
      else
        {
          // The unit disc (or its quarter) extruded along z, then scaled.
          Triangulation<2> disc;
          if (quarter)
            GridGenerator::quarter_hyper_ball(disc, Point<2>(), 1.);
          else
            GridGenerator::hyper_ball(disc, Point<2>(), 1.);
          Triangulation<3> mesh(triangulation.get_mesh_smoothing());
          GridGenerator::extrude_triangulation(disc, height_cells + 1, height / radius, mesh);
          mesh.reset_all_manifolds();
          mesh.set_all_manifold_ids(interior_manifold);
          // Flat faces first, so that the edges they share with the side
          // end up round.
          const double tolerance = 1e-10;
          const auto   on_plane  = [&](const auto &face, const unsigned int axis,
                                    const double value) {
            for (const unsigned int v : face->vertex_indices())
              if (std::abs(face->vertex(v)[axis] - value) > tolerance)
                return false;
            return true;
          };
          std::vector<Triangulation<3>::face_iterator> side_faces;
          for (const auto &cell : mesh.active_cell_iterators())
            for (const auto &face : cell->face_iterators())
              if (face->at_boundary())
                {
                  if (on_plane(face, 2, 0.))
                    face->set_boundary_id(bottom);
                  else if (on_plane(face, 2, height / radius))
                    face->set_boundary_id(top);
                  else if (quarter && on_plane(face, 0, 0.))
                    face->set_boundary_id(x_symmetry);
                  else if (quarter && on_plane(face, 1, 0.))
                    face->set_boundary_id(y_symmetry);
                  else
                    {
                      face->set_boundary_id(side);
                      side_faces.push_back(face);
                      continue;
                    }
                  face->set_all_manifold_ids(numbers::flat_manifold_id);
                }
          for (const auto &face : side_faces)
            face->set_all_manifold_ids(side_manifold);
          GridTools::scale(radius, mesh);
          triangulation.copy_triangulation(mesh);
          triangulation.set_manifold(side_manifold, CylindricalManifold<3>(2));
          TransfiniteInterpolationManifold<3> interior;
          interior.initialize(triangulation);
          triangulation.set_manifold(interior_manifold, interior);
        }
    }



    template <int dim>
    std::map<std::string, types::boundary_id>
    Billet<dim>::boundary_names() const
    {
      using namespace BilletFaces;
      std::map<std::string, types::boundary_id> names = {{"bottom", bottom},
                                                         {"top", top},
                                                         {"side", side}};
      if (dim == 2 || quarter)
        names["x symmetry"] = x_symmetry;
      if (dim == 3 && quarter)
        names["y symmetry"] = y_symmetry;
      return names;
    }

    FRICTIONAL_CONTACT_REGISTER_PLUGIN(
      Interface,
      Billet,
      "billet",
      "A cylindrical billet for upsetting (3D: radius R about the z axis, "
      "height H, whole or the quarter x, y >= 0; 2D: the half section "
      "[0, R] x [0, H] of a plane-strain strip). Boundaries: bottom, top, "
      "side, x symmetry, y symmetry (3D quarter).")
  } // namespace Geometry
} // namespace FrictionalContact
