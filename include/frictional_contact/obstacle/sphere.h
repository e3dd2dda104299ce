#pragma once

#include <frictional_contact/obstacle/interface.h>

namespace FrictionalContact
{
  namespace Obstacle
  {
    /**
     * A rigid ball (a disc in 2D) given by its centre and radius; the body
     * lies outside it.
     */
    template <int dim>
    class Sphere : public Interface<dim>
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
      Point<dim> center;
      double     radius = 1;
    };
  } // namespace Obstacle
} // namespace FrictionalContact
