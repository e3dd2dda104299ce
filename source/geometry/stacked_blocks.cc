#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <frictional_contact/base/plugins.h>
#include <frictional_contact/geometry/mesh_parts.h>
#include <frictional_contact/geometry/stacked_blocks.h>

namespace FrictionalContact
{
  namespace Geometry
  {
    namespace StackedBlockNames
    {
      const char *const bodies[2] = {"base", "block"};

      /// The faces of a colorized box in deal.II's order of boundary ids.
      template <int dim>
      std::vector<std::string>
      faces()
      {
        if (dim == 2)
          return {"left", "right", "bottom", "top"};
        return {"left", "right", "front", "back", "bottom", "top"};
      }
    } // namespace StackedBlockNames



    template <int dim>
    void
    StackedBlocks<dim>::declare_parameters(ParameterHandler &prm)
    {
      const std::string ones  = dim == 2 ? "1, 1" : "1, 1, 1";
      prm.declare_entry("Base extent", dim == 2 ? "1, 1" : "1, 1, 1",
                        Patterns::Anything(),
                        "Size of the base in x, y[, z] (length, > 0); its "
                        "lowest corner is at the origin.");
      prm.declare_entry("Base repetitions", dim == 2 ? "5, 5" : "5, 5, 5",
                        Patterns::Anything(),
                        "Cells of the base in each direction (>= 1).");
      prm.declare_entry("Block extent", ones, Patterns::Anything(),
                        "Size of the block in x, y[, z] (length, > 0).");
      prm.declare_entry("Block repetitions", dim == 2 ? "7, 7" : "7, 7, 7",
                        Patterns::Anything(),
                        "Cells of the block in each direction (>= 1); other "
                        "numbers than the base's make the meshes of the "
                        "interface not match.");
      prm.declare_entry("Block offset", dim == 2 ? "0, 0" : "0, 0, 0",
                        Patterns::Anything(),
                        "Where the block's lowest corner is, relative to the "
                        "point of the base's top at x = 0 (y = 0): the "
                        "sideways shift, and the gap above the base (the last "
                        "component).");
    }



    template <int dim>
    void
    StackedBlocks<dim>::parse_parameters(ParameterHandler &prm)
    {
      const std::string path = "Geometry/Stacked blocks/";
      for (unsigned int k = 0; k < 2; ++k)
        {
          const std::string body = k == 0 ? "Base" : "Block";
          extents[k] = Input::parse_vector<dim>(path + body + " extent",
                                                prm.get(body + " extent"));
          const Tensor<1, dim> cells = Input::parse_vector<dim>(
            path + body + " repetitions", prm.get(body + " repetitions"));
          repetitions[k].clear();
          for (unsigned int d = 0; d < dim; ++d)
            {
              if (!(extents[k][d] > 0))
                Input::fail(path + body + " extent",
                            prm.get(body + " extent"),
                            "positive lengths are expected");
              if (!(cells[d] >= 1 && cells[d] <= 1e4 && cells[d] == std::floor(cells[d])))
                Input::fail(path + body + " repetitions",
                            prm.get(body + " repetitions"),
                            "whole numbers from 1 to 10000 are expected");
              repetitions[k].push_back(static_cast<unsigned int>(cells[d]));
            }
        }
      // A negative gap puts the block into the base: the contact pair
      // refuses that, saying where and how deep.
      block_offset = Input::parse_vector<dim>(path + "Block offset",
                                              prm.get("Block offset"));
    }



    template <int dim>
    void
    StackedBlocks<dim>::create_coarse_mesh(
      parallel::distributed::Triangulation<dim> &triangulation) const
    {
      // Each box on its own, then side by side (create_from_parts).
      Triangulation<dim> boxes[2];
      for (unsigned int k = 0; k < 2; ++k)
        {
          Point<dim> low;
          if (k == 1)
            {
              low = Point<dim>(block_offset);
              low[dim - 1] += extents[0][dim - 1];
            }
          GridGenerator::subdivided_hyper_rectangle(
            boxes[k], repetitions[k], low, low + extents[k], /*colorize=*/true);
          for (const auto &cell : boxes[k].active_cell_iterators())
            {
              cell->set_material_id(k);
              for (const auto &face : cell->face_iterators())
                if (face->at_boundary())
                  face->set_boundary_id(face->boundary_id() + k * 2 * dim);
            }
        }
      create_from_parts(triangulation, {&boxes[0], &boxes[1]});
    }



    template <int dim>
    std::map<std::string, types::boundary_id>
    StackedBlocks<dim>::boundary_names() const
    {
      std::map<std::string, types::boundary_id> names;
      const auto faces = StackedBlockNames::faces<dim>();
      for (unsigned int k = 0; k < 2; ++k)
        for (unsigned int f = 0; f < faces.size(); ++f)
          names[std::string(StackedBlockNames::bodies[k]) + " " + faces[f]] =
            k * 2 * dim + f;
      return names;
    }

    FRICTIONAL_CONTACT_REGISTER_PLUGIN(
      Interface,
      StackedBlocks,
      "stacked blocks",
      "Two bodies: a block on a base, two boxes with their own sizes and "
      "cells (the meshes need not match at the interface), the block above "
      "the base with a gap and a sideways offset. Bodies: base, block. "
      "Boundaries: base left, base right, base bottom, base top (base front, "
      "base back in 3D), and the same for the block.")
  } // namespace Geometry
} // namespace FrictionalContact
