#include <frictional_contact/model/contact_operator.h>

#include <algorithm>

namespace FrictionalContact
{
  // The geometry of ContactOperator that moves: the obstacle's rigid
  // motion, frames that follow the configuration, the pairs' mortar data
  // taken again, and the deepest penetration of the contact boundaries
  // (the class's other members: contact_operator.cc and
  // contact_operator_algebra.cc).

  namespace
  {
    /// dim-1 orthonormal tangents to the unit vector @p n.
    template <int dim>
    std::array<Tensor<1, dim>, dim - 1>
    tangents_to(const Tensor<1, dim> &n)
    {
      std::array<Tensor<1, dim>, dim - 1> t;
      if constexpr (dim == 2)
        {
          t[0][0] = n[1];
          t[0][1] = -n[0];
        }
      else
        {
          // Start from the coordinate axis least aligned with n, so that a
          // normal along z gives the tangents x and y.
          unsigned int axis = 0;
          for (unsigned int d = 1; d < dim; ++d)
            if (std::abs(n[d]) < std::abs(n[axis]))
              axis = d;
          Tensor<1, dim> e;
          e[axis] = 1;
          t[0]    = e - (e * n) * n;
          t[0] /= t[0].norm();
          t[1] = cross_product_3d(n, t[0]);
        }
      return t;
    }

    /// @p v turned by the rotation that takes the unit vector @p from to
    /// @p to about their common normal (the smallest such rotation).
    template <int dim>
    Tensor<1, dim>
    turned(const Tensor<1, dim> &from, const Tensor<1, dim> &to, const Tensor<1, dim> &v)
    {
      const double cosine = from * to;
      if constexpr (dim == 2)
        {
          const double sine = from[0] * to[1] - from[1] * to[0];
          return Tensor<1, dim>({cosine * v[0] - sine * v[1], sine * v[0] + cosine * v[1]});
        }
      else
        {
          const Tensor<1, dim> axis = cross_product_3d(from, to);
          const double         sine = axis.norm();
          if (sine == 0)
            return v;
          const Tensor<1, dim> k = axis / sine;
          return cosine * v + sine * cross_product_3d(k, v) + (1 - cosine) * (k * v) * k;
        }
    }
  } // namespace



  template <int dim>
  Tensor<1, dim>
  ContactOperator<dim>::obstacle_displacement(const double t) const
  {
    Tensor<1, dim> displacement;
    for (unsigned int d = 0; d < dim; ++d)
      displacement[d] = rigid_displacement->value(t, d);
    return displacement;
  }



  template <int dim>
  void
  ContactOperator<dim>::move_obstacle(const Tensor<1, dim> &displacement)
  {
    obstacle_shift = displacement;
    for (unsigned int j = 0; j < nodes.size(); ++j)
      if (nodes[j].pair < 0)
      {
        // A node that follows the configuration is where it was last
        // followed (at first, its reference position).
        const Point<dim> where =
          nodes[j].follows ? nodes[j].position + followed_displacements[j] :
                             nodes[j].position;
        const Tensor<1, dim> normal = obstacle->outward_normal(where - displacement);
        nodes[j].into_obstacle = -normal;
        if (!tangents.empty())
          tangents[j] = tangents_to<dim>(normal);
        if (nodes[j].follows)
          {
            followed_gaps[j]    = obstacle->signed_distance(where - displacement);
            normal_gradients[j] = obstacle->normal_gradient(where - displacement);
          }
      }
  }



  template <int dim>
  void
  ContactOperator<dim>::follow_configuration(const Vector &u)
  {
    for (unsigned int j = 0; j < nodes.size(); ++j)
      if (nodes[j].follows)
        {
          const Tensor<1, dim> u_j = nodal_value(j, u);
          const Point<dim> where = nodes[j].position + u_j - obstacle_shift;
          followed_gaps[j]          = obstacle->signed_distance(where);
          followed_displacements[j] = u_j;
          const Tensor<1, dim> into = -obstacle->outward_normal(where);
          normal_gradients[j]       = obstacle->normal_gradient(where);
          nodes[j].into_obstacle = into;
          turn_tangents(j, into);
        }
  }



  template <int dim>
  void
  ContactOperator<dim>::turn_tangents(const unsigned int j, const Tensor<1, dim> &into)
  {
    if (tangents.empty())
      return;
    // The first tangent turned with the normal, the second across both.
    const Tensor<1, dim> t = tangents[j][0] - (tangents[j][0] * into) * into;
    if (t.norm() > 1e-3)
      {
        tangents[j][0] = t / t.norm();
        if constexpr (dim == 3)
          tangents[j][1] = cross_product_3d(-into, tangents[j][0]);
      }
    else
      tangents[j] = tangents_to<dim>(-into);
  }



  template <int dim>
  bool
  ContactOperator<dim>::pairs_take_tool_frames() const
  {
    return any_pair_follows && tool->geometry_at_every_newton_iterate() &&
           std::all_of(interfaces.begin(), interfaces.end(), [](const auto &interface) {
             return interface.has_rigid_master();
           });
  }



  template <int dim>
  bool
  ContactOperator<dim>::pairs_follow_within_newton() const
  {
    return pairs_take_tool_frames() ||
           (any_pair_follows && bodies_every_newton_iterate &&
            std::any_of(interfaces.begin(), interfaces.end(), [](const auto &interface) {
              return !interface.has_rigid_master();
            }));
  }



  template <int dim>
  void
  ContactOperator<dim>::update_pairs(const ElasticBody<dim> &body,
                                     const Vector           &u_ghosted,
                                     const double            t_start,
                                     const double            t_end,
                                     const Vector           *start)
  {
    for (MortarInterface<dim> &interface : interfaces)
      interface.update(body, u_ghosted, t_start, t_end, start);
    const std::vector<double> previous_gaps = pair_gaps;
    std::vector<Tensor<1, dim>> previous_normals;
    for (const Node &node : nodes)
      previous_normals.push_back(node.into_obstacle);
    pair_gaps.assign(nodes.size(), 0.);
    pair_normal_lengths.assign(nodes.size(), 1.);
    pair_motions.assign(nodes.size(), Tensor<1, dim>());
    frame_slips.assign(nodes.size(), Tensor<1, dim>());
    if (start == nullptr)
      start_normals.assign(nodes.size(), Tensor<1, dim>());
    pair_change = PairChange();
    for (unsigned int j = 0; j < nodes.size(); ++j)
      if (nodes[j].pair >= 0)
        {
          const auto *data = interfaces[nodes[j].pair].node(nodes[j].dofs[0]);
          Assert(data != nullptr, ExcInternalError());
          // A node on a symmetry plane has its own half of the surface
          // only: its averaged normal leans out of the plane. The free
          // components are its normal (unit, so T_j stays orthonormal).
          Tensor<1, dim> normal  = free_part(j, data->normal);
          pair_normal_lengths[j] = normal.norm();
          if (normal.norm() > 0)
            normal /= normal.norm();
          nodes[j].into_obstacle = normal;
          nodes[j].area = data->weight > 0 ? data->weight : data->full_weight;
          pair_gaps[j]  = data->gap;
          if (pairs_take_tool_frames())
            normal_gradients[j] = data->normal_gradient;
          pair_motions[j] = data->master_motion;
          if (start == nullptr)
            start_normals[j] = normal;
          else
            {
              // The node's offset from its mortar point turned as the
              // frame turned, projected on the tangent plane.
              const Tensor<1, dim> offset = -data->offset;
              const Tensor<1, dim> carried =
                offset - turned(start_normals[j], normal, offset);
              frame_slips[j] = carried - (carried * normal) * normal;
            }
          // Within the Newton iterates of an increment the tangents turn
          // with the normal; otherwise they are the normal's own.
          if (start != nullptr && pairs_follow_within_newton())
            turn_tangents(j, normal);
          else if (!tangents.empty())
            tangents[j] = tangents_to<dim>(normal);
          if (previous_gaps.size() == nodes.size())
            {
              pair_change.normal =
                std::max(pair_change.normal, (normal - previous_normals[j]).norm());
              pair_change.gap =
                std::max(pair_change.gap, std::abs(pair_gaps[j] - previous_gaps[j]));
            }
        }
    pair_change.normal = Utilities::MPI::max(pair_change.normal, mpi_communicator);
    pair_change.gap    = Utilities::MPI::max(pair_change.gap, mpi_communicator);
  }



  template <int dim>
  double
  ContactOperator<dim>::deepest_boundary_penetration(
    const ElasticBody<dim> &body,
    const Vector           &u_ghosted) const
  {
    double deepest = 0;
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() &&
              contact_boundaries.count(face->boundary_id()) > 0)
            for (const unsigned int v : face->vertex_indices())
              {
                Point<dim> deformed = face->vertex(v);
                for (unsigned int c = 0; c < dim; ++c)
                  deformed[c] += u_ghosted[face->vertex_dof_index(v, c)];
                deepest = std::max(
                  deepest, -obstacle->signed_distance(deformed - obstacle_shift));
              }
    return Utilities::MPI::max(deepest, mpi_communicator);
  }



  template <int dim>
  void
  ContactOperator<dim>::follow_iterate(const ElasticBody<dim> &body,
                                       const Vector           &u,
                                       const double            t_start,
                                       const double            t_end,
                                       const Vector           &start_ghosted)
  {
    if (follows_configuration())
      follow_configuration(u);
    if (pairs_follow_within_newton())
      {
        Vector ghosted = body.make_ghosted_vector();
        ghosted        = u;
        update_pairs(body, ghosted, t_start, t_end, &start_ghosted);
      }
  }



  template Tensor<1, 2>
  ContactOperator<2>::obstacle_displacement(const double) const;
  template void
  ContactOperator<2>::move_obstacle(const Tensor<1, 2> &);
  template void
  ContactOperator<2>::follow_configuration(const Vector &);
  template void
  ContactOperator<2>::follow_iterate(const ElasticBody<2> &,
                                      const Vector &,
                                      const double,
                                      const double,
                                      const Vector &);
  template bool
  ContactOperator<2>::pairs_follow_within_newton() const;
  template bool
  ContactOperator<2>::pairs_take_tool_frames() const;
  template void
  ContactOperator<2>::update_pairs(const ElasticBody<2> &,
                                    const Vector &,
                                    const double,
                                    const double,
                                    const Vector *);
  template double
  ContactOperator<2>::deepest_boundary_penetration(const ElasticBody<2> &,
                                                    const Vector &) const;
  template Tensor<1, 3>
  ContactOperator<3>::obstacle_displacement(const double) const;
  template void
  ContactOperator<3>::move_obstacle(const Tensor<1, 3> &);
  template void
  ContactOperator<3>::follow_configuration(const Vector &);
  template void
  ContactOperator<3>::follow_iterate(const ElasticBody<3> &,
                                      const Vector &,
                                      const double,
                                      const double,
                                      const Vector &);
  template bool
  ContactOperator<3>::pairs_follow_within_newton() const;
  template bool
  ContactOperator<3>::pairs_take_tool_frames() const;
  template void
  ContactOperator<3>::update_pairs(const ElasticBody<3> &,
                                    const Vector &,
                                    const double,
                                    const double,
                                    const Vector *);
  template double
  ContactOperator<3>::deepest_boundary_penetration(const ElasticBody<3> &,
                                                    const Vector &) const;
} // namespace FrictionalContact
