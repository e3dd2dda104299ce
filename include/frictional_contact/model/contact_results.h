#pragma once

#include <deal.II/base/tensor.h>

#include <frictional_contact/solvers/friction_cone.h>

#include <vector>

namespace FrictionalContact
{
  using namespace dealii;

  /// Per-candidate results of an increment, in the order of the contact operator.
  template <int dim>
  struct ContactResults
  {
    /// Total reaction r^{l+1} and its change over the increment, in the
    /// local frame (r_n, r_t).
    std::vector<Tensor<1, dim>> reaction;
    std::vector<Tensor<1, dim>> reaction_increment;
    /// Normal and tangential displacement increment relative to the
    /// obstacle, T_j^T du - T_j^T (obstacle's displacement increment).
    std::vector<Tensor<1, dim>> local_displacement;
    /// Gap remaining after the increment, g_j - t_n,j^T du (linearised).
    std::vector<double>       gap;
    std::vector<ContactState> state;
    /// Contact pressure -r_n / (lumped nodal area) (force/area, >= 0).
    std::vector<double> pressure;
  };
} // namespace FrictionalContact
