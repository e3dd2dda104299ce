#pragma once

#include <frictional_contact/obstacle/interface.h>

namespace FrictionalContact
{
  namespace Obstacle
  {
    /**
     * A flat rigid obstacle of any orientation: the half-space behind the
     * plane through a point, facing its outward normal.
     */
    template <int dim>
    class Plane : public Interface<dim>
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
      Point<dim>     point_on_plane;
      Tensor<1, dim> normal;
    };
  } // namespace Obstacle
} // namespace FrictionalContact
