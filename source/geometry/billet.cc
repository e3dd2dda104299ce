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

      /**
       * The billet with its neck imperfection: the radius scaled by f(z) =
       * 1 - delta (1 - z / H)^2. Its chart is the straight billet: in 2D
       * (x / f(y), y), for every cell; in 3D the cylindrical coordinates
       * (r / f(z), phi, z), for the side.
       */
      template <int dim>
      class TaperedBillet : public ChartManifold<dim, dim, dim>
      {
      public:
        TaperedBillet(const double delta, const double height)
          : ChartManifold<dim, dim, dim>(periodicity())
          , delta(delta)
          , height(height)
        {}

        std::unique_ptr<Manifold<dim, dim>>
        clone() const override
        {
          return std::make_unique<TaperedBillet<dim>>(delta, height);
        }

        Point<dim>
        pull_back(const Point<dim> &p) const override
        {
          const double scale = factor(p[dim - 1]);
          if constexpr (dim == 2)
            return Point<dim>(p[0] / scale, p[1]);
          else
            return Point<dim>(std::hypot(p[0], p[1]) / scale, std::atan2(p[1], p[0]), p[2]);
        }

        Point<dim>
        push_forward(const Point<dim> &chart) const override
        {
          const double scale = factor(chart[dim - 1]);
          if constexpr (dim == 2)
            return Point<dim>(chart[0] * scale, chart[1]);
          else
            return Point<dim>(chart[0] * scale * std::cos(chart[1]),
                              chart[0] * scale * std::sin(chart[1]),
                              chart[2]);
        }

        DerivativeForm<1, dim, dim>
        push_forward_gradient(const Point<dim> &chart) const override
        {
          const double z = chart[dim - 1], scale = factor(z);
          const double slope = 2. * delta * (1. - z / height) / height;
          DerivativeForm<1, dim, dim> gradient;
          if constexpr (dim == 2)
            {
              gradient[0][0] = scale;
              gradient[0][1] = chart[0] * slope;
              gradient[1][1] = 1;
            }
          else
            {
              const double c = std::cos(chart[1]), s = std::sin(chart[1]);
              gradient[0][0] = scale * c;
              gradient[0][1] = -chart[0] * scale * s;
              gradient[0][2] = chart[0] * slope * c;
              gradient[1][0] = scale * s;
              gradient[1][1] = chart[0] * scale * c;
              gradient[1][2] = chart[0] * slope * s;
              gradient[2][2] = 1;
            }
          return gradient;
        }

        /// f(z).
        double
        factor(const double z) const
        {
          return 1. - delta * (1. - z / height) * (1. - z / height);
        }

      private:
        static Tensor<1, dim>
        periodicity()
        {
          Tensor<1, dim> period;
          if constexpr (dim == 3)
            period[1] = 2. * numbers::PI;
          return period;
        }

        const double delta, height;
      };
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
      prm.declare_entry("Neck imperfection",
                        "0",
                        Patterns::Double(0, 0.5),
                        "delta: the radius (2D: half width) made smaller by "
                        "the fraction delta (1 - z / H)^2, delta at the "
                        "bottom face and none at the top, so that a bar "
                        "pulled by its top face (the bottom its mid-plane) "
                        "necks there; 0: a straight cylinder.");
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
      imperfection = prm.get_double("Neck imperfection");
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
          Triangulation<2> mesh(triangulation.get_mesh_smoothing());
          GridGenerator::subdivided_hyper_rectangle(mesh,
                                                    {2u, height_cells},
                                                    Point<2>(),
                                                    Point<2>(radius, height));
          for (const auto &cell : mesh.active_cell_iterators())
            for (const auto &face : cell->face_iterators())
              if (face->at_boundary())
                {
                  const Point<2> c = face->center();
                  face->set_boundary_id(std::abs(c[1]) < 1e-10 * height          ? bottom :
                                        std::abs(c[1] - height) < 1e-10 * height ? top :
                                        std::abs(c[0]) < 1e-10 * radius          ? x_symmetry :
                                                                                   side);
                }
          const TaperedBillet<2> taper(imperfection, height);
          if (imperfection > 0)
            {
              GridTools::transform([&](const Point<2> &p) { return taper.push_forward(p); },
                                   mesh);
              mesh.set_all_manifold_ids(interior_manifold);
            }
          triangulation.copy_triangulation(mesh);
          if (imperfection > 0)
            triangulation.set_manifold(interior_manifold, taper);
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
          const TaperedBillet<3> taper(imperfection, height);
          if (imperfection > 0)
            GridTools::transform(
              [&](const Point<3> &p) {
                const double scale = taper.factor(p[2]);
                return Point<3>(p[0] * scale, p[1] * scale, p[2]);
              },
              mesh);
          triangulation.copy_triangulation(mesh);
          if (imperfection > 0)
            triangulation.set_manifold(side_manifold, taper);
          else
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
      "side, x symmetry, y symmetry (3D quarter). With a neck imperfection, "
      "a bar for a tensile test.")
  } // namespace Geometry
} // namespace FrictionalContact
