#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include <frictional_contact/base/plugins.h>
#include <frictional_contact/geometry/shell.h>

namespace FrictionalContact
{
  namespace Geometry
  {
    // Named, not anonymous: the unity build puts the geometries side by side.
    namespace ShellFaces
    {
      enum : types::boundary_id
      {
        inner      = 0,
        outer      = 1,
        x_symmetry = 2,
        y_symmetry = 3,
        z_symmetry = 4
      };
    } // namespace ShellFaces



    template <int dim>
    void
    Shell<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Center",
                        dim == 2 ? "0, 0" : "0, 0, 0",
                        Patterns::Anything(),
                        "Centre of the shell (length); the symmetry planes "
                        "go through it.");
      prm.declare_entry("Inner radius",
                        "0.5",
                        Patterns::Double(0.),
                        "Inner radius (length, > 0).");
      prm.declare_entry("Outer radius",
                        "1",
                        Patterns::Double(0.),
                        "Outer radius (length, larger than the inner one).");
      prm.declare_entry("Cells around",
                        "0",
                        Patterns::Integer(0),
                        "2D: coarse cells around the quarter (0: chosen for "
                        "cells of aspect ratio near 1). Ignored in 3D (3 "
                        "coarse cells).");
    }



    template <int dim>
    void
    Shell<dim>::parse_parameters(ParameterHandler &prm)
    {
      center = Point<dim>(
        Input::parse_vector<dim>("Geometry/Shell/Center", prm.get("Center")));
      inner_radius = prm.get_double("Inner radius");
      outer_radius = prm.get_double("Outer radius");
      n_cells      = prm.get_integer("Cells around");
      if (!(inner_radius > 0))
        Input::fail("Geometry/Shell/Inner radius",
                    prm.get("Inner radius"),
                    "the radius must be positive");
      if (!(outer_radius > inner_radius))
        Input::fail("Geometry/Shell/Outer radius",
                    prm.get("Outer radius"),
                    "the outer radius must be larger than the inner radius (" +
                      prm.get("Inner radius") + ")");
    }



    template <int dim>
    void
    Shell<dim>::create_coarse_mesh(
      parallel::distributed::Triangulation<dim> &triangulation) const
    {
      // The mesh's smoothing (with geometric multigrid: one level between
      // neighbours at a vertex) survives the copy below.
      Triangulation<dim> mesh(triangulation.get_mesh_smoothing());
      GridGenerator::quarter_hyper_shell(
        mesh, center, inner_radius, outer_radius, dim == 2 ? n_cells : 0);
      mesh.set_all_manifold_ids(0);

      // Name the faces by where they lie (the flat ones on the planes
      // through the centre). Every cell, face and edge keeps the spherical
      // manifold: it also keeps the flat faces in their planes.
      const auto on_plane = [this](const auto &face, const unsigned int axis) {
        for (const unsigned int v : face->vertex_indices())
          if (std::abs(face->vertex(v)[axis] - center[axis]) >
              1e-10 * outer_radius)
            return false;
        return true;
      };
      const double middle = (inner_radius + outer_radius) / 2;
      for (const auto &cell : mesh.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              if (on_plane(face, 0))
                face->set_boundary_id(ShellFaces::x_symmetry);
              else if (on_plane(face, 1))
                face->set_boundary_id(ShellFaces::y_symmetry);
              else if (dim == 3 && on_plane(face, dim - 1))
                face->set_boundary_id(ShellFaces::z_symmetry);
              else
                face->set_boundary_id(face->center().distance(center) < middle ?
                                        ShellFaces::inner :
                                        ShellFaces::outer);
            }
      triangulation.copy_triangulation(mesh);
      triangulation.set_manifold(0, SphericalManifold<dim>(center));
    }



    template <int dim>
    std::map<std::string, types::boundary_id>
    Shell<dim>::boundary_names() const
    {
      std::map<std::string, types::boundary_id> names = {
        {"inner", ShellFaces::inner},
        {"outer", ShellFaces::outer},
        {"x symmetry", ShellFaces::x_symmetry},
        {"y symmetry", ShellFaces::y_symmetry}};
      if (dim == 3)
        names["z symmetry"] = ShellFaces::z_symmetry;
      return names;
    }

    FRICTIONAL_CONTACT_REGISTER_PLUGIN(
      Interface,
      Shell,
      "shell",
      "A quarter of a thick-walled tube (2D, between two circles) or an "
      "eighth of a thick-walled sphere (3D), cut by the coordinate planes "
      "through its centre: Lame's problem under an internal pressure. "
      "Boundaries: inner, outer, x symmetry, y symmetry, z symmetry.")
  } // namespace Geometry
} // namespace FrictionalContact
