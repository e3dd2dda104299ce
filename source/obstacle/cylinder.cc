#include <frictional_contact/obstacle/cylinder.h>
#include <frictional_contact/base/plugins.h>

namespace FrictionalContact
{
  namespace Obstacle
  {
    template <int dim>
    void
    Cylinder<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Point on axis",
                        dim == 2 ? "0, 0" : "0, 0, 0",
                        Patterns::Anything(),
                        "A point on the cylinder's axis (length).");
      if (dim == 3)
        prm.declare_entry("Axis direction",
                          "0, 1, 0",
                          Patterns::Anything(),
                          "Direction of the axis (need not be unit length, "
                          "must not be zero).");
      prm.declare_entry("Radius",
                        "1",
                        Patterns::Double(0.),
                        "Radius of the cylinder (length, > 0).");
    }



    template <int dim>
    void
    Cylinder<dim>::parse_parameters(ParameterHandler &prm)
    {
      axis_point = Point<dim>(Input::parse_vector<dim>(
        "Contact/Obstacle/Cylinder/Point on axis", prm.get("Point on axis")));
      if (dim == 3)
        {
          axis = Input::parse_vector<dim>(
            "Contact/Obstacle/Cylinder/Axis direction",
            prm.get("Axis direction"));
          if (!(axis.norm() > 0))
            Input::fail("Contact/Obstacle/Cylinder/Axis direction",
                        prm.get("Axis direction"),
                        "the direction must not be zero");
          axis /= axis.norm();
        }
      radius = prm.get_double("Radius");
      if (!(radius > 0))
        Input::fail("Contact/Obstacle/Cylinder/Radius",
                    prm.get("Radius"),
                    "the radius must be positive");
    }



    template <int dim>
    Tensor<1, dim>
    Cylinder<dim>::radial(const Point<dim> &point) const
    {
      const Tensor<1, dim> offset = point - axis_point;
      return offset - (offset * axis) * axis;
    }



    template <int dim>
    double
    Cylinder<dim>::signed_distance(const Point<dim> &point) const
    {
      return radial(point).norm() - radius;
    }



    template <int dim>
    Tensor<1, dim>
    Cylinder<dim>::outward_normal(const Point<dim> &point) const
    {
      const Tensor<1, dim> r      = radial(point);
      const double         length = r.norm();
      if (length > 0)
        return r / length;
      // On the axis every direction normal to it is nearest: pick one.
      Tensor<1, dim> any;
      any[0] = 1;
      any -= (any * axis) * axis;
      if (any.norm() == 0)
        any[1] = 1;
      return any / any.norm();
    }

    template <int dim>
    Tensor<2, dim>
    Cylinder<dim>::normal_gradient(const Point<dim> &point) const
    {
      // (I - a a^T - n n^T) / |r|: the normal turns with the motion around
      // the axis a (in 2D a = 0), not along it.
      const double length = radial(point).norm();
      if (!(length > 0))
        return {};
      const Tensor<1, dim> n = outward_normal(point);
      return (Tensor<2, dim>(unit_symmetric_tensor<dim>()) - outer_product(axis, axis) -
              outer_product(n, n)) /
             length;
    }

    FRICTIONAL_CONTACT_REGISTER_PLUGIN(
      Interface,
      Cylinder,
      "cylinder",
      "A rigid circular cylinder of infinite length (in 2D a disc: the axis "
      "is normal to the plane); the body lies outside it.")
  } // namespace Obstacle
} // namespace FrictionalContact
