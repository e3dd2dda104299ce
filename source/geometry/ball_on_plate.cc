#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <frictional_contact/base/plugins.h>
#include <frictional_contact/geometry/ball_on_plate.h>
#include <frictional_contact/geometry/mesh_parts.h>
#include <frictional_contact/geometry/half_ball.h>

namespace FrictionalContact
{
  namespace Geometry
  {
    namespace BallOnPlateFaces
    {
      /// The ball's faces keep half_ball_mesh()'s ids 0 to 3; the plate's
      /// (a colorized box: x, y[, z] low and high) start here.
      constexpr types::boundary_id first_plate_face = 10;

      template <int dim>
      std::vector<std::string>
      plate_faces()
      {
        if (dim == 2)
          return {"left", "right", "bottom", "top"};
        return {"left", "right", "front", "back", "bottom", "top"};
      }
    } // namespace BallOnPlateFaces



    template <int dim>
    void
    BallOnPlate<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Radius", "1", Patterns::Double(0.),
                        "Radius of the ball (disc in 2D) (length, > 0).");
      prm.declare_entry("Gap", "0", Patterns::Double(0.),
                        "Distance of the ball's lowest point above the plate "
                        "(length, >= 0).");
      prm.declare_entry("Symmetry planes", "0", Patterns::Integer(0, 2),
                        "0: all of it; 1: only x >= 0 (hold 'ball x "
                        "symmetry' and 'plate left' in x); 2 (3D): only x, y "
                        ">= 0 (also 'ball y symmetry' and 'plate front' in y).");
      prm.declare_entry("Plate width", "2", Patterns::Double(0.),
                        "How far the plate reaches from the axis of the ball "
                        "in x (and y) (length, > 0).");
      prm.declare_entry("Plate thickness", "1", Patterns::Double(0.),
                        "Thickness of the plate (length, > 0).");
      prm.declare_entry("Plate cells", dim == 2 ? "8, 4" : "8, 8, 4",
                        Patterns::Anything(),
                        "Cells of the plate in x, y[, z] before refinement.");
    }



    template <int dim>
    void
    BallOnPlate<dim>::parse_parameters(ParameterHandler &prm)
    {
      const std::string path = "Geometry/Ball on plate/";
      radius            = prm.get_double("Radius");
      gap               = prm.get_double("Gap");
      n_symmetry_planes = prm.get_integer("Symmetry planes");
      plate_width       = prm.get_double("Plate width");
      plate_thickness   = prm.get_double("Plate thickness");
      for (const auto &[entry, value] :
           {std::pair<std::string, double>{"Radius", radius},
            {"Plate width", plate_width},
            {"Plate thickness", plate_thickness}})
        if (!(value > 0))
          Input::fail(path + entry, prm.get(entry), "a positive length is expected");
      if (n_symmetry_planes > dim - 1)
        Input::fail(path + "Symmetry planes", prm.get("Symmetry planes"),
                    "a 2D scene has at most 1 symmetry plane");
      const Tensor<1, dim> cells =
        Input::parse_vector<dim>(path + "Plate cells", prm.get("Plate cells"));
      plate_cells.clear();
      for (unsigned int d = 0; d < dim; ++d)
        {
          if (!(cells[d] >= 1 && cells[d] <= 1e4 && cells[d] == std::floor(cells[d])))
            Input::fail(path + "Plate cells", prm.get("Plate cells"),
                        "whole numbers from 1 to 10000 are expected");
          plate_cells.push_back(static_cast<unsigned int>(cells[d]));
        }
    }



    template <int dim>
    void
    BallOnPlate<dim>::create_coarse_mesh(
      parallel::distributed::Triangulation<dim> &triangulation) const
    {
      Point<dim> center;
      center[dim - 1] = radius + gap;
      Triangulation<dim> ball;
      half_ball_mesh(ball, center, radius, n_symmetry_planes);

      // The plate below the plane through the origin, cut where the ball is.
      Point<dim> low, high;
      for (unsigned int d = 0; d < dim - 1; ++d)
        {
          low[d]  = d < n_symmetry_planes ? 0. : -plate_width;
          high[d] = plate_width;
        }
      low[dim - 1] = -plate_thickness;
      Triangulation<dim> plate;
      GridGenerator::subdivided_hyper_rectangle(plate, plate_cells, low, high, true);

      // Side by side, their shared vertices kept apart (create_from_parts).
      for (const auto &cell : ball.active_cell_iterators())
        cell->set_material_id(1);
      for (const auto &cell : plate.active_cell_iterators())
        {
          cell->set_material_id(0);
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              face->set_boundary_id(BallOnPlateFaces::first_plate_face +
                                    face->boundary_id());
        }
      create_from_parts(triangulation, {&plate, &ball});
      attach_half_ball_manifolds(triangulation, center);
    }



    template <int dim>
    std::map<std::string, types::boundary_id>
    BallOnPlate<dim>::boundary_names() const
    {
      std::map<std::string, types::boundary_id> names = {{"ball curved", 0},
                                                         {"ball top", 1}};
      if (n_symmetry_planes >= 1)
        names["ball x symmetry"] = 2;
      if (n_symmetry_planes >= 2)
        names["ball y symmetry"] = 3;
      const auto faces = BallOnPlateFaces::plate_faces<dim>();
      for (unsigned int f = 0; f < faces.size(); ++f)
        names["plate " + faces[f]] = BallOnPlateFaces::first_plate_face + f;
      return names;
    }

    FRICTIONAL_CONTACT_REGISTER_PLUGIN(
      Interface,
      BallOnPlate,
      "ball on plate",
      "Two bodies: the lower half of a ball (disc in 2D) resting on a plate, "
      "optionally cut by symmetry planes through the ball's axis. Bodies: "
      "plate, ball. Boundaries: ball curved, ball top, ball x symmetry, ball "
      "y symmetry, plate left, plate right, plate bottom, plate top (plate "
      "front, plate back in 3D).")
  } // namespace Geometry
} // namespace FrictionalContact
