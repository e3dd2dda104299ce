#pragma once

#include <deal.II/base/tensor.h>

#include <frictional_contact/model/contact_operator.h>
#include <frictional_contact/model/contact_results.h>

#include <array>

namespace FrictionalContact
{
  /// The contact of an increment in a few numbers, summed over all ranks.
  template <int dim>
  struct ContactSummary
  {
    /// Candidates free, sticking and slipping (in ContactState's order).
    std::array<unsigned int, 3> counts = {{0, 0, 0}};
    /// The total contact force (Cartesian; of a pair, the force on its slave
    /// side), its normal part (>= 0 when pressing) and the magnitude of its
    /// tangential part.
    Tensor<1, dim> force;
    /// The part of the force the obstacle exerts: what the bodies as a
    /// whole feel (a pair's forces cancel).
    Tensor<1, dim> external_force;
    double         normal_force     = 0;
    double         tangential_force = 0;
    /// Lumped areas of the candidates in contact and of those sticking.
    double contact_area = 0;
    double stick_area   = 0;
    double max_pressure = 0;
    /// The deepest penetration of any contact-boundary vertex (candidates,
    /// hanging nodes, fixed nodes) into the obstacle.
    double deepest_penetration = 0;

    unsigned int
    count(const ContactState state) const
    {
      return counts[static_cast<int>(state)];
    }
  };

  /// The summary of @p results with the contact forces @p contact_forces;
  /// @p axisymmetric: the forces are totals over the revolution.
  template <int dim>
  ContactSummary<dim>
  summarize(const ContactOperator<dim>        &contact,
            const ContactResults<dim>         &results,
            const std::vector<Tensor<1, dim>> &contact_forces,
            const bool                         axisymmetric,
            const MPI_Comm                     comm);
} // namespace FrictionalContact
