#include <frictional_contact/obstacle/sphere.h>
#include <frictional_contact/base/plugins.h>

namespace FrictionalContact
{
  namespace Obstacle
  {
    template <int dim>
    void
    Sphere<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Center",
                        dim == 2 ? "0, 0" : "0, 0, 0",
                        Patterns::Anything(),
                        "Centre of the ball (length).");
      prm.declare_entry("Radius",
                        "1",
                        Patterns::Double(0.),
                        "Radius of the ball (length, > 0).");
    }



    template <int dim>
    void
    Sphere<dim>::parse_parameters(ParameterHandler &prm)
    {
      center = Point<dim>(Input::parse_vector<dim>(
        "Contact/Obstacle/Sphere/Center", prm.get("Center")));
      radius = prm.get_double("Radius");
      if (!(radius > 0))
        Input::fail("Contact/Obstacle/Sphere/Radius",
                    prm.get("Radius"),
                    "the radius must be positive");
    }



    template <int dim>
    double
    Sphere<dim>::signed_distance(const Point<dim> &point) const
    {
      return point.distance(center) - radius;
    }



    template <int dim>
    Tensor<1, dim>
    Sphere<dim>::outward_normal(const Point<dim> &point) const
    {
      const Tensor<1, dim> radial = point - center;
      const double         length = radial.norm();
      if (length > 0)
        return radial / length;
      Tensor<1, dim> any; // the centre itself: every direction is nearest
      any[dim - 1] = 1;
      return any;
    }

    template <int dim>
    Tensor<2, dim>
    Sphere<dim>::normal_gradient(const Point<dim> &point) const
    {
      // (I - n n^T) / |x - c|: the normal turns with the tangential motion.
      const double length = (point - center).norm();
      if (!(length > 0))
        return {};
      const Tensor<1, dim> n = outward_normal(point);
      return (unit_symmetric_tensor<dim>() - outer_product(n, n)) / length;
    }

    FRICTIONAL_CONTACT_REGISTER_PLUGIN(
      Interface,
      Sphere,
      "sphere",
      "A rigid ball (a disc in 2D); the body lies outside it.")
  } // namespace Obstacle
} // namespace FrictionalContact
