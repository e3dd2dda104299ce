#pragma once

#include <frictional_contact/obstacle/interface.h>

namespace FrictionalContact
{
  namespace Obstacle
  {
    /**
     * A rigid circular cylinder of infinite length: a point on its axis,
     * the axis direction (3D only; in 2D the axis is normal to the plane and
     * the cylinder is a disc) and the radius. The body lies outside it.
     */
    template <int dim>
    class Cylinder : public Interface<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      double
      signed_distance(const Point<dim> &point) const override;

      Tensor<1, dim>
      outward_normal(const Point<dim> &point) const override;

      Tensor<2, dim>
      normal_gradient(const Point<dim> &point) const override;

    private:
      /// The part of point - axis_point normal to the axis.
      Tensor<1, dim>
      radial(const Point<dim> &point) const;

      Point<dim>     axis_point;
      Tensor<1, dim> axis; // unit; zero in 2D
      double         radius = 1;
    };
  } // namespace Obstacle
} // namespace FrictionalContact
