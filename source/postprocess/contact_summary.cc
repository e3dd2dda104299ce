#include <deal.II/base/mpi.h>

#include <frictional_contact/model/axisymmetry.h>
#include <frictional_contact/postprocess/contact_summary.h>

namespace FrictionalContact
{
  template <int dim>
  ContactSummary<dim>
  summarize(const ContactOperator<dim>        &contact,
            const ContactResults<dim>         &results,
            const std::vector<Tensor<1, dim>> &contact_forces,
            const bool                         axisymmetric,
            const MPI_Comm                     comm)
  {
    ContactSummary<dim> s;
    Tensor<1, dim>      tangential_force;
    for (unsigned int j = 0; j < results.state.size(); ++j)
      {
        ++s.counts[static_cast<int>(results.state[j])];
        if (results.state[j] != ContactState::free)
          s.contact_area += contact.nodal_area(j);
        if (results.state[j] == ContactState::stick)
          s.stick_area += contact.nodal_area(j);
        s.max_pressure = std::max(s.max_pressure, results.pressure[j]);
        s.force += contact_forces[j];
        if (!contact.acts_between_bodies(j))
          s.external_force += contact_forces[j];
        s.normal_force -= results.reaction[j][0];
        Tensor<1, dim> normal_part;
        normal_part[0] = results.reaction[j][0];
        tangential_force +=
          contact_forces[j] - contact.to_cartesian(j, normal_part);
      }
    unsigned int counts[3] = {s.counts[0], s.counts[1], s.counts[2]};
    Utilities::MPI::sum(counts, comm, counts);
    s.counts = {{counts[0], counts[1], counts[2]}};
    s.force            = Utilities::MPI::sum(s.force, comm);
    s.external_force   = Utilities::MPI::sum(s.external_force, comm);
    s.normal_force     = Utilities::MPI::sum(s.normal_force, comm);
    tangential_force   = Utilities::MPI::sum(tangential_force, comm);
    if (axisymmetric)
      {
        s.force          = Axisymmetry::revolution_total(s.force);
        s.external_force = Axisymmetry::revolution_total(s.external_force);
        tangential_force = Axisymmetry::revolution_total(tangential_force);
      }
    s.tangential_force = tangential_force.norm();
    s.contact_area     = Utilities::MPI::sum(s.contact_area, comm);
    s.stick_area       = Utilities::MPI::sum(s.stick_area, comm);
    s.max_pressure     = Utilities::MPI::max(s.max_pressure, comm);
    return s;
  }

  template ContactSummary<2>
  summarize(const ContactOperator<2> &,
            const ContactResults<2> &,
            const std::vector<Tensor<1, 2>> &,
            const bool,
            const MPI_Comm);
  template ContactSummary<3>
  summarize(const ContactOperator<3> &,
            const ContactResults<3> &,
            const std::vector<Tensor<1, 3>> &,
            const bool,
            const MPI_Comm);
} // namespace FrictionalContact
