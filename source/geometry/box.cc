#include <deal.II/grid/grid_generator.h>

#include <frictional_contact/geometry/box.h>
#include <frictional_contact/base/plugins.h>

namespace FrictionalContact
{
  namespace Geometry
  {
    namespace
    {
      const char *axis_name[3] = {"X", "Y", "Z"};
    }



    template <int dim>
    void
    Box<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Origin",
                        dim == 2 ? "0, 0" : "0, 0, 0",
                        Patterns::Anything(),
                        "Coordinates of the corner with the smallest "
                        "coordinates (length).");
      for (unsigned int d = 0; d < dim; ++d)
        {
          prm.declare_entry(std::string(axis_name[d]) + " extent",
                            "1",
                            Patterns::Double(0.),
                            std::string("Size of the box in ") + axis_name[d] +
                              " direction (length, > 0).");
          prm.declare_entry(std::string(axis_name[d]) + " repetitions",
                            "10",
                            Patterns::Integer(1),
                            std::string("Number of cells in ") + axis_name[d] +
                              " direction (>= 1), before global refinement.");
        }
    }



    template <int dim>
    void
    Box<dim>::parse_parameters(ParameterHandler &prm)
    {
      origin = Point<dim>(
        Input::parse_vector<dim>("Geometry/Box/Origin", prm.get("Origin")));
      for (unsigned int d = 0; d < dim; ++d)
        {
          const std::string axis = axis_name[d];
          extents[d]             = prm.get_double(axis + " extent");
          if (!(extents[d] > 0))
            Input::fail("Geometry/Box/" + axis + " extent",
                        prm.get(axis + " extent"),
                        "the extent must be positive");
          repetitions[d] = prm.get_integer(axis + " repetitions");
        }

      double cells = 1;
      for (unsigned int d = 0; d < dim; ++d)
        cells *= repetitions[d];
      if (cells > 1e8)
        Input::fail("Geometry/Box/X repetitions",
                    prm.get("X repetitions"),
                    "the repetitions make " + Input::to_text(cells) +
                      " cells, more than 1e8; use fewer");

      // The coarse mesh lives on every MPI rank: keep it small by halving
      // the repetitions while all of them stay integer, and refine back.
      n_halvings = 0;
      while (true)
        {
          bool all_even = true;
          for (unsigned int d = 0; d < dim; ++d)
            all_even = all_even && (repetitions[d] >> n_halvings) % 2 == 0;
          if (!all_even)
            break;
          ++n_halvings;
        }
    }



    template <int dim>
    void
    Box<dim>::create_coarse_mesh(
      parallel::distributed::Triangulation<dim> &triangulation) const
    {
      std::vector<unsigned int> coarse_repetitions(dim);
      for (unsigned int d = 0; d < dim; ++d)
        coarse_repetitions[d] = repetitions[d] >> n_halvings;
      GridGenerator::subdivided_hyper_rectangle(triangulation,
                                                coarse_repetitions,
                                                origin,
                                                origin + extents,
                                                /*colorize=*/true);
    }



    template <int dim>
    unsigned int
    Box<dim>::n_built_in_refinements() const
    {
      return n_halvings;
    }



    template <int dim>
    std::map<std::string, types::boundary_id>
    Box<dim>::boundary_names() const
    {
      if (dim == 2)
        return {{"left", 0}, {"right", 1}, {"bottom", 2}, {"top", 3}};
      return {{"left", 0},
              {"right", 1},
              {"front", 2},
              {"back", 3},
              {"bottom", 4},
              {"top", 5}};
    }

    FRICTIONAL_CONTACT_REGISTER_PLUGIN(
      Interface,
      Box,
      "box",
      "A rectangle (2D) or brick (3D) divided into equal cells. Boundaries: "
      "left, right (x), bottom, top (y) in 2D; left, right (x), front, back "
      "(y), bottom, top (z) in 3D.")
  } // namespace Geometry
} // namespace FrictionalContact
