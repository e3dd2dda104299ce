#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>

#include <map>
#include <string>

namespace FrictionalContact
{
  namespace Geometry
  {
    using namespace dealii;

    /**
     * A geometry model: creates the coarse mesh of the elastic body, sets its
     * boundary ids (on all coarse cells, before any refinement) and names
     * them. Implementations register themselves with
     * FRICTIONAL_CONTACT_REGISTER_PLUGIN(Geometry::Interface, ...); see
     * doc/adding-a-geometry.md.
     */
    template <int dim>
    class Interface
    {
    public:
      virtual ~Interface() = default;

      /// Reads this model's subsection (the caller has entered it).
      virtual void
      parse_parameters(ParameterHandler &prm) = 0;

      /// Fills the empty @p triangulation with the coarse mesh.
      virtual void
      create_coarse_mesh(
        parallel::distributed::Triangulation<dim> &triangulation) const = 0;

      /**
       * How many times the coarse mesh is refined globally to get the mesh
       * the user asked for (the Box builds a small coarse mesh and refines).
       */
      virtual unsigned int
      n_built_in_refinements() const
      {
        return 0;
      }

      /// Symbolic names of the boundary ids, usable in the parameter file.
      virtual std::map<std::string, types::boundary_id>
      boundary_names() const = 0;

      /**
       * The bodies of the scene, by name, and the material id their cells
       * carry. One body by default, "body", whose cells the model gives
       * material id 0; a geometry that makes several bodies sets the ids of
       * their coarse cells and names them here.
       */
      virtual std::map<std::string, types::material_id>
      body_names() const
      {
        return {{"body", 0}};
      }
    };
  } // namespace Geometry
} // namespace FrictionalContact
