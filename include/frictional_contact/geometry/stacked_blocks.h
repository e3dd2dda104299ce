#pragma once

#include <frictional_contact/geometry/interface.h>

#include <array>

namespace FrictionalContact
{
  namespace Geometry
  {
    /**
     * Two bodies, a block on a base: two boxes of their own sizes and
     * cells, the block above the base (along y in 2D, z in 3D) with a gap
     * and a sideways offset, in one mesh whose bodies share no vertex (so
     * their meshes need not match at the interface). Bodies: base (material
     * id 0) and block (1). Boundaries: the box names of each, prefixed with
     * the body: base left, base right, base bottom, base top (and base
     * front, base back in 3D), block left, and so on.
     */
    template <int dim>
    class StackedBlocks : public Interface<dim>
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

      std::map<std::string, types::material_id>
      body_names() const override
      {
        return {{"base", 0}, {"block", 1}};
      }

    private:
      /// Extents and cells of the base (0) and the block (1).
      std::array<Tensor<1, dim>, 2>                extents;
      std::array<std::vector<unsigned int>, 2>     repetitions;
      /// The block's lowest corner relative to the base's top at x = 0.
      Tensor<1, dim>                               block_offset;
    };
  } // namespace Geometry
} // namespace FrictionalContact
