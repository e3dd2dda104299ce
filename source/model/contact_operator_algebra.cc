#include <deal.II/base/symmetric_tensor.h>

#include <frictional_contact/model/contact_operator.h>

namespace FrictionalContact
{
  template <int dim>
  Tensor<1, dim>
  ContactOperator<dim>::turning_force(const unsigned int    j,
                                      const Tensor<1, dim> &r_j,
                                      const Tensor<1, dim> &turn) const
  {
    Tensor<1, dim> tangential = r_j;
    tangential[0]             = 0;
    return r_j[0] * turn -
           (to_cartesian(j, tangential) * turn) * nodes[j].into_obstacle;
  }



  template <int dim>
  Tensor<1, dim>
  ContactOperator<dim>::free_part(const unsigned int j, Tensor<1, dim> v) const
  {
    for (unsigned int c = 0; c < dim; ++c)
      if (!nodes[j].free[c])
        v[c] = 0;
    return v;
  }



  // The nodal algebra of ContactOperator: the local frames of the
  // candidates, T and the forces of both sides of a pair, the normal
  // stiffness and nodal blocks the Newton method asks for, and the largest
  // singular value of T (the class's other members: contact_operator.cc).



  template <int dim>
  Tensor<1, dim>
  ContactOperator<dim>::to_local(const unsigned int j, Tensor<1, dim> v) const
  {
    v = free_part(j, v);
    Tensor<1, dim> local;
    local[0] = nodes[j].into_obstacle * v;
    if (!tangents.empty())
      for (unsigned int k = 0; k < dim - 1; ++k)
        local[k + 1] = tangents[j][k] * v;
    return local;
  }



  template <int dim>
  Tensor<1, dim>
  ContactOperator<dim>::to_cartesian(const unsigned int    j,
                                     const Tensor<1, dim> &v) const
  {
    Tensor<1, dim> x = v[0] * nodes[j].into_obstacle;
    if (!tangents.empty())
      for (unsigned int k = 0; k < dim - 1; ++k)
        x += v[k + 1] * tangents[j][k];
    return free_part(j, x);
  }



  template <int dim>
  void
  ContactOperator<dim>::normal_turns(const Vector                &u,
                                     std::vector<Tensor<1, dim>> &turns) const
  {
    turns.assign(nodes.size(), Tensor<1, dim>());
    const bool pairs_turn = pairs_take_tool_frames();
    for (unsigned int j = 0; j < nodes.size(); ++j)
      {
        const bool pair_turns = pairs_turn && nodes[j].pair >= 0 && pair_normal_lengths[j] > 0;
        if (!nodes[j].follows && !pair_turns)
          continue;
        turns[j] = normal_gradients[j] * free_part(j, nodal_value(j, u));
        if (pair_turns)
          {
            // A tool's normal n turns with the node's move along it; t_n is
            // -P n / |P n|, P leaving out the fixed components.
            const Tensor<1, dim>  turn = free_part(j, turns[j]);
            const Tensor<1, dim> &into = nodes[j].into_obstacle;
            turns[j] = (turn - (turn * into) * into) / pair_normal_lengths[j];
          }
      }
  }



  template <int dim>
  void
  ContactOperator<dim>::add_frame_stiffness(const std::vector<Tensor<1, dim>> &r,
                                            const Vector                      &u,
                                            Vector                            &f) const
  {
    normal_turns(u, turns_scratch);
    for (unsigned int j = 0; j < nodes.size(); ++j)
      if (turns_scratch[j].norm_square() > 0)
        {
          add_nodal_value(j, free_part(j, turning_force(j, r[j], turns_scratch[j])), f);
        }
  }



  template <int dim>
  void
  ContactOperator<dim>::add_force_beyond_frames(const std::vector<Tensor<1, dim>> &r,
                                                const std::vector<Tensor<1, dim>> &turns,
                                                const double                       scale,
                                                Vector                            &f) const
  {
    // A node of a pair between two bodies is left out: its whole force is
    // held across the geometry (MortarBasis::follow_reactions()). Against
    // the rigid tool in its frames, its frame turns with its mortar point
    // as with an obstacle's closest point (the tool's faces projected
    // along its vertex normals, MortarInterface::update()).
    const bool tool_frames = pairs_take_tool_frames();
    for (unsigned int j = 0; j < turns.size(); ++j)
      if ((nodes[j].pair < 0 || tool_frames) && turns[j].norm_square() > 0)
        {
          const Tensor<1, dim> force = free_part(j, turning_force(j, r[j], scale * turns[j]));
          add_nodal_value(j, force - to_cartesian(j, to_local(j, force)), f);
        }
  }



  template <int dim>
  void
  ContactOperator<dim>::set_nodal_values(
    const std::vector<Tensor<1, dim>> &values,
    Vector                            &f) const
  {
    f = 0;
    for (unsigned int j = 0; j < nodes.size(); ++j)
      add_nodal_value(j, values[j], f);
  }



  template <int dim>
  void
  ContactOperator<dim>::apply(const std::vector<Tensor<1, dim>> &r,
                              Vector                            &f) const
  {
    f = 0;
    for (unsigned int j = 0; j < nodes.size(); ++j)
      add_nodal_value(j, to_cartesian(j, r[j]), f);
  }



  template <int dim>
  void
  ContactOperator<dim>::forces_on_both_sides(const std::vector<Tensor<1, dim>> &r,
                                             Vector &f) const
  {
    apply(r, f);
    if (!has_pairs())
      return;
    // The master nodes of this rank's slave nodes may lie beyond its ghost
    // layer, and the same dof may get several slave nodes' parts: the parts
    // are summed here, written into a vector whose non-local entries are
    // exactly the dofs written, and added over the ranks.
    std::map<types::global_dof_index, double> parts;
    for (unsigned int j = 0; j < nodes.size(); ++j)
      if (nodes[j].pair >= 0)
        if (const auto *data = interfaces[nodes[j].pair].node(nodes[j].dofs[0]))
          {
            const Tensor<1, dim> force = to_cartesian(j, r[j]);
            for (const auto &[dofs, p] : data->masters)
              for (unsigned int c = 0; c < dim; ++c)
                interfaces[nodes[j].pair].resolve_master_dof(
                  dofs[c], [&](const types::global_dof_index dof, const double w) {
                    parts[dof] -= p * w * force[c];
                  });
          }
    IndexSet written(f.size());
    for (const auto &[dof, part] : parts)
      written.add_index(dof);
    written.compress();
    Vector master;
    master.reinit(f.locally_owned_elements(), written, mpi_communicator, true);
    for (const auto &[dof, part] : parts)
      master[dof] += part;
    master.compress(VectorOperation::add);
    f += master;
  }



  template <int dim>
  std::vector<double>
  ContactOperator<dim>::normal_stiffness(const StiffnessOperator &K) const
  {
    std::vector<std::vector<types::global_dof_index>> node_dofs;
    for (const auto &node : nodes)
      node_dofs.emplace_back(node.dofs.begin(), node.dofs.end());
    const std::vector<FullMatrix<double>> blocks = K.blocks(node_dofs);
    std::vector<double> c(nodes.size(), 0.);
    for (unsigned int j = 0; j < nodes.size(); ++j)
      {
        Tensor<1, dim> normal;
        normal[0]                = 1;
        const Tensor<1, dim> t_n = to_cartesian(j, normal);
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            c[j] += t_n[a] * blocks[j](a, b) * t_n[b];
      }
    return c;
  }



  template <int dim>
  bool
  ContactOperator<dim>::nodal_block(const unsigned int    j,
                                    const Tensor<2, dim> &B,
                                    NodalBlock           &block) const
  {
    Tensor<2, dim> frame; // columns: the local directions, Cartesian
    for (unsigned int a = 0; a < dim; ++a)
      {
        Tensor<1, dim> e;
        e[a]                          = 1;
        const Tensor<1, dim> column   = to_cartesian(j, e);
        for (unsigned int c = 0; c < dim; ++c)
          frame[c][a] = column[c];
      }
    const Tensor<2, dim> cartesian = frame * B * transpose(frame);
    block.dofs.assign(nodes[j].dofs.begin(), nodes[j].dofs.end());
    block.values.resize(dim * dim);
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int b = 0; b < dim; ++b)
        block.values[a * dim + b] = cartesian[a][b];
    return true;
  }



  template <int dim>
  double
  ContactOperator<dim>::largest_singular_value() const
  {
    // Candidates sit on distinct nodes, so T^T T is block diagonal with the
    // blocks T_j^T T_j, and sigma_T^2 is the largest of their eigenvalues.
    double largest = 0;
    for (unsigned int j = 0; j < nodes.size(); ++j)
      {
        SymmetricTensor<2, dim> gram;
        for (unsigned int a = 0; a < dim; ++a)
          {
            Tensor<1, dim> e;
            e[a]                           = 1;
            const Tensor<1, dim> column_a  = to_cartesian(j, e);
            for (unsigned int b = 0; b <= a; ++b)
              {
                Tensor<1, dim> f;
                f[b]       = 1;
                gram[a][b] = column_a * to_cartesian(j, f);
              }
          }
        largest = std::max(largest, eigenvalues(gram)[0]);
      }
    return std::sqrt(Utilities::MPI::max(largest, mpi_communicator));
  }



  template <int dim>
  double
  ContactOperator<dim>::orthonormality_defect() const
  {
    const unsigned int n_columns = has_friction() ? dim : 1;
    double             defect    = 0;
    for (unsigned int j = 0; j < nodes.size(); ++j)
      for (unsigned int a = 0; a < n_columns; ++a)
        for (unsigned int b = 0; b < n_columns; ++b)
          {
            Tensor<1, dim> e, f;
            e[a] = 1;
            f[b] = 1;
            defect = std::max(defect,
                              std::abs(to_cartesian(j, e) * to_cartesian(j, f) -
                                       (a == b ? 1. : 0.)));
          }
    return Utilities::MPI::max(defect, mpi_communicator);
  }



  template <int dim>
  Tensor<1, dim>
  ContactOperator<dim>::gap_slope(const unsigned int j) const
  {
    if (nodes[j].pair >= 0)
      if (const auto *data = interfaces[nodes[j].pair].node(nodes[j].dofs[0]))
        return to_local(j, data->gap_slope);
    return Tensor<1, dim>();
  }



  // Each member apart: contact_operator.cc instantiates the class, and a
  // unity build may put both files in one translation unit.
  template Tensor<1, 2>
  ContactOperator<2>::to_local(const unsigned int, Tensor<1, 2>) const;
  template Tensor<1, 3>
  ContactOperator<3>::to_local(const unsigned int, Tensor<1, 3>) const;
  template Tensor<1, 2>
  ContactOperator<2>::to_cartesian(const unsigned int, const Tensor<1, 2> &) const;
  template Tensor<1, 3>
  ContactOperator<3>::to_cartesian(const unsigned int, const Tensor<1, 3> &) const;
  template void
  ContactOperator<2>::set_nodal_values(const std::vector<Tensor<1, 2>> &,
                                       Vector &) const;
  template void
  ContactOperator<3>::set_nodal_values(const std::vector<Tensor<1, 3>> &,
                                       Vector &) const;
  template void
  ContactOperator<2>::apply(const std::vector<Tensor<1, 2>> &, Vector &) const;
  template void
  ContactOperator<3>::apply(const std::vector<Tensor<1, 3>> &, Vector &) const;
  template void
  ContactOperator<2>::forces_on_both_sides(const std::vector<Tensor<1, 2>> &,
                                           Vector &) const;
  template void
  ContactOperator<3>::forces_on_both_sides(const std::vector<Tensor<1, 3>> &,
                                           Vector &) const;
  template std::vector<double>
  ContactOperator<2>::normal_stiffness(const StiffnessOperator &) const;
  template std::vector<double>
  ContactOperator<3>::normal_stiffness(const StiffnessOperator &) const;
  template bool
  ContactOperator<2>::nodal_block(const unsigned int,
                                  const Tensor<2, 2> &,
                                  NodalBlock &) const;
  template bool
  ContactOperator<3>::nodal_block(const unsigned int,
                                  const Tensor<2, 3> &,
                                  NodalBlock &) const;
  template Tensor<1, 2>
  ContactOperator<2>::gap_slope(const unsigned int) const;
  template Tensor<1, 3>
  ContactOperator<3>::gap_slope(const unsigned int) const;
  template double
  ContactOperator<2>::largest_singular_value() const;
  template double
  ContactOperator<3>::largest_singular_value() const;
  template double
  ContactOperator<2>::orthonormality_defect() const;
  template double
  ContactOperator<3>::orthonormality_defect() const;
  template void
  ContactOperator<2>::normal_turns(const Vector &, std::vector<Tensor<1, 2>> &) const;
  template void
  ContactOperator<3>::normal_turns(const Vector &, std::vector<Tensor<1, 3>> &) const;
  template void
  ContactOperator<2>::add_frame_stiffness(const std::vector<Tensor<1, 2>> &,
                                          const Vector &,
                                          Vector &) const;
  template void
  ContactOperator<3>::add_frame_stiffness(const std::vector<Tensor<1, 3>> &,
                                          const Vector &,
                                          Vector &) const;
  template void
  ContactOperator<2>::add_force_beyond_frames(const std::vector<Tensor<1, 2>> &,
                                              const std::vector<Tensor<1, 2>> &,
                                              const double,
                                              Vector &) const;
  template void
  ContactOperator<3>::add_force_beyond_frames(const std::vector<Tensor<1, 3>> &,
                                              const std::vector<Tensor<1, 3>> &,
                                              const double,
                                              Vector &) const;
  template Tensor<1, 2>
  ContactOperator<2>::turning_force(const unsigned int,
                                      const Tensor<1, 2> &,
                                      const Tensor<1, 2> &) const;
  template Tensor<1, 2>
  ContactOperator<2>::free_part(const unsigned int, Tensor<1, 2>) const;
  template Tensor<1, 3>
  ContactOperator<3>::turning_force(const unsigned int,
                                      const Tensor<1, 3> &,
                                      const Tensor<1, 3> &) const;
  template Tensor<1, 3>
  ContactOperator<3>::free_part(const unsigned int, Tensor<1, 3>) const;
} // namespace FrictionalContact
