#include <frictional_contact/driver/increment_response.h>

namespace FrictionalContact
{
  template <int dim>
  IncrementResponse<dim>::IncrementResponse(Model<dim>       &model,
                                            MortarBasis<dim> *mortar,
                                            const Vector     &start,
                                            const Vector     &lifting)
    : model(model)
    , mortar(mortar)
    , start(start)
    , force_at_start(model.get_body().make_vector())
    , u(force_at_start)
    , u_ghosted(model.get_body().make_ghosted_vector())
    , force(force_at_start)
    , du_in_u(force_at_start)
  {
    // f_int and the tangent at u^l = u_0 - lifting; the derivative along
    // the lifting by a difference quotient over a small part of it.
    const AffineConstraints<double> &constraints = model.get_body().get_constraints();
    const double                     size        = lifting.linfty_norm();
    Vector                           ahead       = force_at_start;
    u                                            = start;
    u -= lifting;
    double epsilon = 0;
    if (size > 0)
      {
        epsilon = 1e-7 * std::max(start.linfty_norm(), size) / size;
        u.add(epsilon, lifting);
        u_ghosted = u;
        model.get_response().internal_force(u_ghosted, constraints, ahead, nullptr);
        u.add(-epsilon, lifting);
      }
    u_ghosted = u;
    plastic   = model.update_tangent(u_ghosted, force);
    if (mortar != nullptr)
      mortar->update_tangent(model.get_body().stiffness().matrix("contact pairs"), true);
    scale = model.get_response().element_force_norm();
    // f_int(u^l) + (f_int(u^l + eps lifting) - f_int(u^l)) / eps.
    force_at_start = force;
    if (size > 0)
      {
        ahead -= force;
        force_at_start.add(1. / epsilon, ahead);
      }
  }



  template <int dim>
  void
  IncrementResponse<dim>::take_in_u(const Vector &du)
  {
    if (mortar != nullptr)
      mortar->displacement_to_u(du, du_in_u);
    else
      du_in_u = du;
  }



  template <int dim>
  void
  IncrementResponse<dim>::move_to(const Vector &du)
  {
    u = du;
    // The held dofs stay (their increment is in u_0), hanging ones follow.
    model.get_body().get_constraints().distribute(u);
    u += start;
    u_ghosted = u;
  }



  template <int dim>
  void
  IncrementResponse<dim>::evaluate(const Vector &du, const bool with_tangent)
  {
    move_to(du);
    if (with_tangent)
      {
        plastic = model.update_tangent(u_ghosted, force);
        if (mortar != nullptr)
          mortar->update_tangent(model.get_body().stiffness().matrix("contact pairs"), false);
      }
    else
      plastic = model.get_response().internal_force(
        u_ghosted, model.get_body().get_constraints(), force, nullptr);
    scale = model.get_response().element_force_norm();
  }



  template <int dim>
  void
  IncrementResponse<dim>::internal_force_change(const Vector &du,
                                                Vector       &dst,
                                                const bool    with_tangent)
  {
    take_in_u(du);
    if (linear && !with_tangent)
      // The linearised start: K_T(u^l) du.
      model.get_body().stiffness().vmult(force, du_in_u);
    else
      {
        linear = false;
        evaluate(du_in_u, with_tangent);
        force -= force_at_start;
      }
    if (mortar != nullptr)
      {
        mortar->force_to_w(force, dst);
        mortar->add_geometry_change(du, dst, 1.);
      }
    else
      dst = force;
  }

  template <int dim>
  std::string
  IncrementResponse<dim>::worst_place(const Vector &du)
  {
    take_in_u(du);
    move_to(du_in_u);
    const PlacedMinimum<dim> smallest = model.get_response().smallest_jacobian(u_ghosted);
    if (!smallest.met())
      return {};
    return "the smallest det F, " + Input::to_text(smallest.value) +
           ", is in the cell at " + smallest.place();
  }

  template class IncrementResponse<2>;
  template class IncrementResponse<3>;
} // namespace FrictionalContact
