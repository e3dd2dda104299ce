#include <frictional_contact/driver/contact_geometry_at_iterates.h>

namespace FrictionalContact
{
  template <int dim>
  ContactGeometryAtIterates<dim>::ContactGeometryAtIterates(
    ContactOperator<dim>    &contact,
    IncrementalProblem<dim> &problem,
    const ElasticBody<dim>  &body,
    MortarBasis<dim>        *mortar,
    Vector                  &load,
    const Vector            &start,
    const double             t_start,
    const double             t_end,
    const Tensor<1, dim>    &obstacle_motion)
    : contact(contact)
    , problem(problem)
    , body(body)
    , mortar(mortar)
    , load(load)
    , start(start)
    , t_start(t_start)
    , t_end(t_end)
    , obstacle_motion(obstacle_motion)
  {
    if (contact.pairs_follow_within_newton())
      {
        start_ghosted = body.make_ghosted_vector();
        start_ghosted = start;
      }
  }



  template <int dim>
  void
  ContactGeometryAtIterates<dim>::follow(Vector                      &du,
                                         std::vector<Tensor<1, dim>> &r,
                                         Vector                      &K_du)
  {
    // The reactions keep their Cartesian direction.
    std::vector<Tensor<1, dim>> forces(r.size());
    for (unsigned int j = 0; j < r.size(); ++j)
      forces[j] = contact.to_cartesian(j, r[j]);
    const AffineConstraints<double> &constraints = body.get_constraints();
    const bool rows_change = contact.mortar_rows_change_within_newton();
    // The iterate in u (du is in w, which is u where no row changes).
    Vector du_in_u = du, force;
    if (rows_change)
      {
        // K du as the law gives it (without the geometry's predicted change).
        mortar->add_geometry_change(du, K_du, -1.);
        mortar->displacement_to_u(du, du_in_u);
        constraints.distribute(du_in_u);
        force = K_du;
        mortar->force_to_u(force, K_du);
        force = load;
        mortar->force_to_u(force, load);
      }
    Vector solved = du_in_u;
    solved += start;
    contact.follow_iterate(body, solved, t_start, t_end, start_ghosted);
    if (rows_change)
      {
        // The same iterate and forces in the basis of the new rows.
        mortar->follow_rows(body, contact);
        mortar->displacement_to_w(du_in_u, du);
        constraints.set_zero(du);
        mortar->follow_reactions(body, contact, forces, du);
        force = K_du;
        mortar->force_to_w(force, K_du);
        force = load;
        mortar->force_to_w(force, load);
      }
    // Where the rows follow the iterates, so does the gap as a node
    // slides: gap_at() is the gap at the iterate, to first order about it.
    problem.gap_slopes.resize(rows_change ? r.size() : 0);
    for (unsigned int j = 0; j < r.size(); ++j)
      {
        problem.gaps[j]          = contact.gap_at_start(j, start);
        problem.obstacle_slip[j] = contact.prescribed_slip(j, obstacle_motion);
        r[j]                     = contact.to_local(j, forces[j]);
        if (!problem.gap_slopes.empty())
          {
            problem.gap_slopes[j] = contact.gap_slope(j);
            const Tensor<1, dim> u_j = problem.relative_displacement(j, du);
            problem.gaps[j] -= problem.gap_slopes[j] * u_j;
          }
      }
  }



  template <int dim>
  bool
  ContactGeometryAtIterates<dim>::turns_pair_frames() const
  {
    return contact.mortar_rows_change_within_newton();
  }



  template <int dim>
  void
  ContactGeometryAtIterates<dim>::pair_frame_turns(const Vector                &step,
                                                   std::vector<Tensor<1, dim>> &turns) const
  {
    mortar->frame_turns(contact, step, turns);
  }



  template class ContactGeometryAtIterates<2>;
  template class ContactGeometryAtIterates<3>;
} // namespace FrictionalContact
