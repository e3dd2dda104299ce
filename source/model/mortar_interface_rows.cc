#include <deal.II/base/mpi.h>

#include <frictional_contact/model/mortar_interface.h>

#include <map>
#include <vector>

namespace FrictionalContact
{
  // The slave nodes' data from the sums over the faces: the rows P_jl and
  // gaps of a deformable master (M's entries summed over the ranks here),
  // or the gaps and motions of a rigid tool (MortarInterface::update()).



  template <int dim>
  Point<dim>
  MortarInterface<dim>::start_node(const types::global_dof_index dof,
                                   const Vector                 &normal_sum,
                                   const Vector                 &lumped_sum,
                                   const Vector                 &u_ghosted)
  {
    const auto &[dofs, reference] = slave_vertices.at(dof);
    SlaveNode  &node              = nodes[dof];
    node                          = SlaveNode();
    Point<dim> position           = reference;
    for (unsigned int c = 0; c < dim; ++c)
      {
        node.normal[c] = normal_sum[dofs[c]];
        position[c] += u_ghosted[dofs[c]];
      }
    node.normal /= node.normal.norm();
    node.full_weight = lumped_sum[dof];
    return position;
  }



  template <int dim>
  bool
  MortarInterface<dim>::covered(SlaveNode &node) const
  {
    // A node the master hardly covers gets no mortar row: it is free this
    // increment (a weight near 0 would make P_jl = M_jl / D_jj huge).
    if (node.weight > 1e-3 * node.full_weight)
      return true;
    node.weight = 0;
    node.gap    = reach;
    return false;
  }



  template <int dim>
  void
  MortarInterface<dim>::finish_rows(
    const Vector     &normal_sum,
    const Vector     &lumped_sum,
    const RowEntries &M_entries,
    const std::map<types::global_dof_index, MasterVertex> &master_vertex,
    const Vector   &gap_displacement,
    const Vector   &u_ghosted,
    const MPI_Comm  comm)
  {
    // The rows of M, summed over the ranks: rows are the slave vertices' x
    // dofs, columns the master vertices'. A row this rank does not own goes
    // to its owner (the entries are few: a matrix of all of the body's rows
    // cost more than the rest of the update).
    const IndexSet &owned = normal_sum.locally_owned_elements();
    IndexSet        rows_here(owned.size());
    for (const auto &[entry, value] : M_entries)
      rows_here.add_index(entry.first);
    rows_here.compress();
    const std::vector<unsigned int> owners =
      Utilities::MPI::compute_index_owner(owned, rows_here, comm);
    const unsigned int this_rank = Utilities::MPI::this_mpi_process(comm);
    std::map<unsigned int, std::vector<MortarEntry>>           to_owners;
    std::map<types::global_dof_index, std::map<types::global_dof_index, RowEntry>> rows;
    for (const auto &[position, entry] : M_entries)
      {
        const unsigned int owner = owners[rows_here.index_within_set(position.first)];
        if (owner == this_rank)
          rows[position.first][position.second] += entry;
        else
          to_owners[owner].push_back({position.first, position.second, entry});
      }
    for (const auto &[rank, entries] : Utilities::MPI::some_to_some(comm, to_owners))
      for (const MortarEntry &entry : entries)
        rows[entry.row][entry.column] += entry.entry;

    for (auto &[dof, node] : nodes)
      {
        const Point<dim> position =
          start_node(dof, normal_sum, lumped_sum, gap_displacement);
        Point<dim> current = slave_vertices.at(dof).second;
        for (unsigned int c = 0; c < dim; ++c)
          current[c] += u_ghosted[slave_vertices.at(dof).first[c]];
        std::vector<std::pair<types::global_dof_index, RowEntry>> row;
        if (const auto found = rows.find(dof); found != rows.end())
          for (const auto &[column, entry] : found->second)
            if (entry.value != 0)
              {
                row.emplace_back(column, entry);
                node.weight += entry.value;
              }
        if (!covered(node))
          continue;
        for (const auto &[column, entry] : row)
          {
            const MasterVertex &master = master_vertex.at(column);
            const double        p      = entry.value / node.weight;
            node.masters.emplace_back(master.dofs, p);
            node.master_slides.push_back(entry.slide / node.weight);
            node.gap += p * (node.normal * (master.at_gaps - position));
            node.offset += p * (master.at_gaps - position);
            node.gap_slope +=
              node.master_slides.back() * (node.normal * (master.current - current));
          }
      }
  }



  template <int dim>
  void
  MortarInterface<dim>::finish_rigid_rows(const Vector    &normal_sum,
                                          const Vector    &lumped_sum,
                                          const RigidRows &rigid,
                                          const Vector    &u_ghosted)
  {
    for (auto &[dof, node] : nodes)
      {
        const Point<dim> position = start_node(dof, normal_sum, lumped_sum, u_ghosted);
        node.weight               = rigid.weight[dof];
        if (!covered(node))
          continue;
        const NodeDofs &dofs = slave_vertices.at(dof).first;
        Tensor<1, dim>  mean_point;
        for (unsigned int c = 0; c < dim; ++c)
          {
            mean_point[c]         = rigid.point[dofs[c]] / node.weight;
            node.master_motion[c] = rigid.motion[dofs[c]] / node.weight;
          }
        if (tool_frames)
          {
            // n = N / |N|, so dn = (I - n n^T) dN / |N|.
            Tensor<1, dim> tool_normal;
            Tensor<2, dim> gradient;
            for (unsigned int c = 0; c < dim; ++c)
              {
                tool_normal[c] = rigid.normal[dofs[c]] / node.weight;
                for (unsigned int k = 0; k < dim; ++k)
                  gradient[k][c] = rigid.curvature[k][dofs[c]] / node.weight;
              }
            const double length = tool_normal.norm();
            tool_normal /= length;
            node.normal = -tool_normal;
            // The tool's shape operator: its tangential part, symmetric
            // (as a smooth surface's is; the interpolated normals' is only
            // nearly), so that a Newton system without slip stays one for
            // CG.
            const Tensor<2, dim> across =
              Tensor<2, dim>(unit_symmetric_tensor<dim>()) -
              outer_product(tool_normal, tool_normal);
            node.normal_gradient =
              Tensor<2, dim>(symmetrize(across * gradient * across)) / length;
          }
        node.gap    = node.normal * (mean_point - position);
        node.offset = mean_point - node.master_motion - position;
      }
  }


  // Each member apart: mortar_interface.cc instantiates the class, and a
  // unity build may put both files in one translation unit.
  template Point<2>
  MortarInterface<2>::start_node(const types::global_dof_index,
                                  const Vector &,
                                  const Vector &,
                                  const Vector &);
  template bool
  MortarInterface<2>::covered(SlaveNode &) const;
  template void
  MortarInterface<2>::finish_rows(const Vector &,
                                   const Vector &,
                                   const RowEntries &,
                                   const std::map<types::global_dof_index, MasterVertex> &,
                                   const Vector &,
                                   const Vector &,
                                   const MPI_Comm);
  template void
  MortarInterface<2>::finish_rigid_rows(const Vector &,
                                         const Vector &,
                                         const RigidRows &,
                                         const Vector &);
  template Point<3>
  MortarInterface<3>::start_node(const types::global_dof_index,
                                  const Vector &,
                                  const Vector &,
                                  const Vector &);
  template bool
  MortarInterface<3>::covered(SlaveNode &) const;
  template void
  MortarInterface<3>::finish_rows(const Vector &,
                                   const Vector &,
                                   const RowEntries &,
                                   const std::map<types::global_dof_index, MasterVertex> &,
                                   const Vector &,
                                   const Vector &,
                                   const MPI_Comm);
  template void
  MortarInterface<3>::finish_rigid_rows(const Vector &,
                                         const Vector &,
                                         const RigidRows &,
                                         const Vector &);
} // namespace FrictionalContact
