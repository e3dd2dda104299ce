#pragma once

#include <deal.II/grid/tria.h>

#include <vector>

namespace FrictionalContact
{
  namespace Geometry
  {
    using namespace dealii;

    /**
     * Makes @p triangulation the coarse mesh of @p parts side by side: their
     * cells with their material, boundary and manifold ids as they are, and
     * the vertices two parts share at an interface kept apart (one copy per
     * part), as two bodies in contact need; merging the meshes would join
     * them.
     */
    template <int dim>
    void
    create_from_parts(Triangulation<dim>                            &triangulation,
                      const std::vector<const Triangulation<dim> *> &parts);
  } // namespace Geometry
} // namespace FrictionalContact
