#include <frictional_contact/obstacle/plane.h>
#include <frictional_contact/base/plugins.h>

namespace FrictionalContact
{
  namespace Obstacle
  {
    template <int dim>
    void
    Plane<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Point",
                        dim == 2 ? "0, 0" : "0, 0, 0",
                        Patterns::Anything(),
                        "A point on the obstacle's surface (length).");
      prm.declare_entry("Outward normal",
                        dim == 2 ? "0, 1" : "0, 0, 1",
                        Patterns::Anything(),
                        "The normal of the surface pointing out of the "
                        "obstacle, towards the body. Need not be unit length, "
                        "must not be zero.");
    }



    template <int dim>
    void
    Plane<dim>::parse_parameters(ParameterHandler &prm)
    {
      point_on_plane = Point<dim>(Input::parse_vector<dim>(
        "Contact/Obstacle/Plane/Point", prm.get("Point")));
      normal = Input::parse_vector<dim>("Contact/Obstacle/Plane/Outward normal",
                                        prm.get("Outward normal"));
      if (!(normal.norm() > 0))
        Input::fail("Contact/Obstacle/Plane/Outward normal",
                    prm.get("Outward normal"),
                    "the normal must not be zero");
      normal /= normal.norm();
    }



    template <int dim>
    double
    Plane<dim>::signed_distance(const Point<dim> &point) const
    {
      return normal * (point - point_on_plane);
    }



    template <int dim>
    Tensor<1, dim>
    Plane<dim>::outward_normal(const Point<dim> &) const
    {
      return normal;
    }

    template <int dim>
    Tensor<2, dim>
    Plane<dim>::normal_gradient(const Point<dim> &) const
    {
      return {};
    }

    FRICTIONAL_CONTACT_REGISTER_PLUGIN(
      Interface,
      Plane,
      "plane",
      "A flat rigid obstacle through a point, with a given outward normal.")
  } // namespace Obstacle
} // namespace FrictionalContact
