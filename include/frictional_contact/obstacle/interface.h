#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

namespace FrictionalContact
{
  namespace Obstacle
  {
    using namespace dealii;

    /**
     * A rigid obstacle, described by the signed distance to its surface
     * (positive outside the obstacle, where the body is) and the unit
     * outward normal of the surface at the point nearest to a given point.
     * Implementations register themselves with
     * FRICTIONAL_CONTACT_REGISTER_PLUGIN(Obstacle::Interface, ...); see
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

      /// Signed distance from @p point to the surface, > 0 outside.
      virtual double
      signed_distance(const Point<dim> &point) const = 0;

      /// Unit outward normal at the surface point nearest to @p point.
      virtual Tensor<1, dim>
      outward_normal(const Point<dim> &point) const = 0;

      /// The gradient of outward_normal() at @p point: the surface's
      /// curvature, which the contact force of a body sliding over a curved
      /// obstacle follows (zero for a plane).
      virtual Tensor<2, dim>
      normal_gradient(const Point<dim> &point) const = 0;
    };
  } // namespace Obstacle
} // namespace FrictionalContact
