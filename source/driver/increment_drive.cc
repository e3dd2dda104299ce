#include <frictional_contact/driver/increment_drive.h>

#include <cmath>
#include <utility>

namespace FrictionalContact
{
  template <int dim>
  IncrementDrive<dim>::IncrementDrive(const TrilinosWrappers::MPI::Vector &lifting,
                                      std::vector<std::vector<double>> rigid_parts)
    : lifting(lifting)
    , rigid_parts(std::move(rigid_parts))
  {}



  template <int dim>
  std::vector<std::vector<double>>
  IncrementDrive<dim>::rigid_parts_of(const double                load_factor_change,
                                      const ContactOperator<dim> &contact,
                                      const double                t_start,
                                      const double                t_end)
  {
    std::vector<std::vector<double>> parts{{load_factor_change}};
    const Tensor<1, dim> obstacle =
      contact.obstacle_displacement(t_end) - contact.obstacle_displacement(t_start);
    parts.emplace_back(obstacle.begin_raw(), obstacle.end_raw());
    const RigidTool<dim> &tool = contact.rigid_tool();
    if (tool.active())
      {
        const Tensor<1, dim> translation =
          tool.translation_at(t_end) - tool.translation_at(t_start);
        parts.emplace_back(translation.begin_raw(), translation.end_raw());
        parts.push_back({tool.angle_at(t_end) - tool.angle_at(t_start)});
      }
    return parts;
  }



  template <int dim>
  bool
  IncrementDrive<dim>::same_way(const double dot,
                                const double this_norm2,
                                const double last_norm2,
                                const double ratio)
  {
    // A part that stays still goes on; one that starts or stops moving
    // (smaller than 1e-12 of the other) turns.
    if (this_norm2 == 0 && last_norm2 == 0)
      return true;
    if (this_norm2 <= 1e-24 * last_norm2 || last_norm2 <= 1e-24 * this_norm2)
      return false;
    const double size_ratio = std::sqrt(this_norm2 / last_norm2) / ratio;
    return dot >= std::cos(25. * numbers::PI / 180.) * std::sqrt(this_norm2 * last_norm2) &&
           size_ratio >= 0.5 && size_ratio <= 2;
  }



  template <int dim>
  bool
  IncrementDrive<dim>::continues(const IncrementDrive &last,
                                 const double          length,
                                 const double          last_length) const
  {
    if (last.rigid_parts.size() != rigid_parts.size() || !(last_length > 0) ||
        last.lifting.size() != lifting.size() ||
        Utilities::MPI::logical_or(last.lifting.locally_owned_elements() !=
                                     lifting.locally_owned_elements(),
                                   lifting.get_mpi_communicator()))
      return false;
    const double ratio = length / last_length;
    if (!same_way(lifting * last.lifting, lifting.norm_sqr(), last.lifting.norm_sqr(), ratio))
      return false;
    for (unsigned int p = 0; p < rigid_parts.size(); ++p)
      {
        double dot = 0, this_norm2 = 0, last_norm2 = 0;
        for (unsigned int i = 0; i < rigid_parts[p].size(); ++i)
          {
            dot += rigid_parts[p][i] * last.rigid_parts[p][i];
            this_norm2 += rigid_parts[p][i] * rigid_parts[p][i];
            last_norm2 += last.rigid_parts[p][i] * last.rigid_parts[p][i];
          }
        if (!same_way(dot, this_norm2, last_norm2, ratio))
          return false;
      }
    return true;
  }



  template class IncrementDrive<2>;
  template class IncrementDrive<3>;
} // namespace FrictionalContact
