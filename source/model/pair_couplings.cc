#include <deal.II/base/mpi.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <cstddef>

#include <frictional_contact/model/contact_operator.h>
#include <frictional_contact/model/pair_couplings.h>

namespace FrictionalContact
{
  namespace
  {
    // The (row, column) of a position or of an entry.
    const Couplings::key_type &
    key_of(const Couplings::key_type &position)
    {
      return position;
    }

    const Couplings::key_type &
    key_of(const Couplings::value_type &entry)
    {
      return entry.first;
    }
  } // namespace



  void
  CouplingMatrix::take(const IndexSet  &owned,
                       const MPI_Comm   comm,
                       const Couplings &entries,
                       const bool       identity)
  {
    // In place where the pattern already holds every entry (both are
    // sorted by row and column): within an increment the couplings mostly
    // keep their positions or gain some as slave nodes reach new segments.
    const bool same_rows = matrix.m() > 0 && matrix.locally_owned_range_indices() == owned;
    const bool in_place =
      same_rows &&
      std::includes(positions.begin(), positions.end(), entries.begin(), entries.end(),
                    [](const auto &a, const auto &b) { return key_of(a) < key_of(b); });
    if (Utilities::MPI::logical_or(!in_place, comm))
      {
        // The new pattern keeps the old positions too (on the same rows),
        // so that couplings that come and go do not remake it each time.
        if (!same_rows)
          positions.clear();
        const auto kept = static_cast<std::ptrdiff_t>(positions.size());
        for (const auto &[position, value] : entries)
          positions.push_back(position);
        std::inplace_merge(positions.begin(), positions.begin() + kept, positions.end());
        positions.erase(std::unique(positions.begin(), positions.end()), positions.end());
        TrilinosWrappers::SparsityPattern pattern(owned, owned, owned, comm);
        if (identity)
          for (const auto i : owned)
            pattern.add(i, i);
        for (const auto &[row, column] : positions)
          pattern.add(row, column);
        pattern.compress();
        matrix.reinit(pattern);
        if (identity)
          for (const auto i : owned)
            matrix.set(i, i, 1.);
      }
    // Every position is set again: to its entry's value, or where it has
    // none now to the identity's or zero. One call per row, not per entry.
    std::vector<types::global_dof_index> columns;
    std::vector<double>                  values;
    auto                                 entry = entries.begin();
    for (auto position = positions.begin(); position != positions.end();)
      {
        const types::global_dof_index row = position->first;
        columns.clear();
        values.clear();
        for (; position != positions.end() && position->first == row; ++position)
          {
            const bool has_entry = entry != entries.end() && entry->first == *position;
            const bool diagonal  = position->first == position->second;
            columns.push_back(position->second);
            values.push_back(has_entry ? (entry++)->second : identity && diagonal ? 1. : 0.);
          }
        matrix.set(row, columns.size(), columns.data(), values.data());
      }
    matrix.compress(VectorOperation::insert);
  }



  template <int dim>
  Couplings
  PairCouplings<dim>::basis() const
  {
    Couplings couplings;
    for (const auto &node : contact.nodes)
      if (node.pair >= 0)
        if (const auto *data = contact.interfaces[node.pair].node(node.dofs[0]))
          for (const auto &[master, p] : data->masters)
            for (unsigned int c = 0; c < dim; ++c)
              if (node.free[c])
                contact.interfaces[node.pair].resolve_master_dof(
                  master[c], [&](const types::global_dof_index unknown, const double weight) {
                    couplings[{node.dofs[c], unknown}] += p * weight;
                  });
    return couplings;
  }



  template <int dim>
  Couplings
  PairCouplings<dim>::sliding(const std::vector<Tensor<1, dim>> &forces) const
  {
    Couplings couplings;
    for (unsigned int j = 0; j < contact.nodes.size(); ++j)
      {
        const auto &node = contact.nodes[j];
        if (node.pair < 0 || forces[j].norm_square() == 0)
          continue;
        const auto &interface = contact.interfaces[node.pair];
        if (const auto *data = interface.node(node.dofs[0]))
          for (unsigned int l = 0; l < data->masters.size(); ++l)
            for (unsigned int b = 0; b < dim; ++b)
              interface.resolve_master_dof(
                data->masters[l].first[b],
                [&](const types::global_dof_index unknown, const double weight) {
                  for (unsigned int a = 0; a < dim; ++a)
                    if (node.free[a])
                      couplings[{node.dofs[a], unknown}] +=
                        weight * data->master_slides[l][a] * forces[j][b];
                });
      }
    return couplings;
  }



  template <int dim>
  std::vector<std::pair<std::array<types::global_dof_index, dim>, Tensor<2, dim>>>
  PairCouplings<dim>::turns_per_move(const unsigned int j) const
  {
    const auto &node   = contact.nodes[j];
    const double length = contact.pair_normal_lengths[j];
    std::vector<std::pair<std::array<types::global_dof_index, dim>, Tensor<2, dim>>> per_move;
    if (node.pair < 0 || length == 0)
      return per_move;
    const auto *data = contact.interfaces[node.pair].node(node.dofs[0]);
    if (data == nullptr)
      return per_move;
    // t_n = P N / |P N| (P: the free components, N the unit averaged
    // normal) turns by (I - t_n t_n^T) P dN / |P N|; what the node
    // touches, its outward normal, by minus that.
    const Tensor<1, dim> &n      = node.into_obstacle;
    const Tensor<2, dim>  across = Tensor<2, dim>(unit_symmetric_tensor<dim>()) - outer_product(n, n);
    for (const auto &[dofs, derivative] : data->normal_derivatives)
      {
        Tensor<2, dim> free_derivative = derivative;
        for (unsigned int c = 0; c < dim; ++c)
          if (!node.free[c])
            free_derivative[c] = Tensor<1, dim>();
        per_move.emplace_back(dofs, -across * free_derivative / length);
      }
    return per_move;
  }



  template <int dim>
  Couplings
  PairCouplings<dim>::turns(const std::vector<Tensor<1, dim>> *forces) const
  {
    Couplings couplings;
    for (unsigned int j = 0; j < contact.nodes.size(); ++j)
      {
        if (forces != nullptr && (*forces)[j].norm_square() == 0)
          continue;
        const auto &node = contact.nodes[j];
        // The turn itself, or the force of the frame's turn
        // (ContactOperator::turning_force(), linear in the turn).
        Tensor<2, dim> per_turn = unit_symmetric_tensor<dim>();
        if (forces != nullptr)
          {
            const Tensor<1, dim> &n   = node.into_obstacle;
            const double          r_n = n * (*forces)[j];
            per_turn = r_n * per_turn - outer_product(n, (*forces)[j] - r_n * n);
          }
        for (const auto &[dofs, turn] : turns_per_move(j))
          {
            const Tensor<2, dim> entry = per_turn * turn;
            for (unsigned int a = 0; a < dim; ++a)
              if (node.free[a])
                for (unsigned int b = 0; b < dim; ++b)
                  if (entry[a][b] != 0)
                    couplings[{node.dofs[a], dofs[b]}] += entry[a][b];
          }
      }
    return couplings;
  }

  template class PairCouplings<2>;
  template class PairCouplings<3>;
} // namespace FrictionalContact
