#include <frictional_contact/base/placed_minimum.h>
#include <frictional_contact/solvers/contact_problem.h>

#include <cmath>

namespace FrictionalContact
{
  template <int dim>
  std::vector<double>
  contact_stiffness(const IncrementalProblem<dim> &problem, std::vector<double> c)
  {
    if (!problem.master_stiffness.empty())
      for (unsigned int j = 0; j < c.size(); ++j)
        {
          const double m = problem.master_stiffness[j];
          if (c[j] > 0 && m > 0 && std::isfinite(m))
            c[j] = c[j] * m / (c[j] + m);
        }
    return c;
  }



  template <int dim>
  Residuals
  compute_residuals(const IncrementalProblem<dim>       &problem,
                    const TrilinosWrappers::MPI::Vector &du,
                    const TrilinosWrappers::MPI::Vector &K_du,
                    const TrilinosWrappers::MPI::Vector &T_r,
                    const std::vector<Tensor<1, dim>>   &r,
                    TrilinosWrappers::MPI::Vector       &scratch)
  {
    scratch = K_du;
    scratch -= problem.load;
    scratch -= T_r;

    const ContactMap<dim>      &contact = problem.contact;
    double local[2]                     = {0., 0.};
    for (unsigned int j = 0; j < contact.n_local(); ++j)
      {
        const Tensor<1, dim> u_j = problem.relative_displacement(j, du);
        const double         gap = problem.gap_at(j, u_j);
        Tensor<1, dim>       v   = u_j;
        v[0] = -gap - contact.friction_coefficient(j) *
                        FrictionCone<dim>::tangential_norm(u_j);
        local[0] += v * r[j];
        local[1] += std::pow(std::min(gap, 0.), 2);
      }
    double global[2];
    Utilities::MPI::sum(local, du.get_mpi_communicator(), global);

    Residuals residuals;
    residuals.force_balance   = scratch.l2_norm();
    residuals.complementarity = std::abs(global[0]);
    residuals.penetration     = std::sqrt(global[1]);
    return residuals;
  }

  template <int dim>
  std::string
  worst_places(const IncrementalProblem<dim> &problem, const TrilinosWrappers::MPI::Vector &du)
  {
    const ContactMap<dim> &contact = problem.contact;
    PlacedMinimum<dim>     deepest;
    for (unsigned int j = 0; j < contact.n_local(); ++j)
      deepest.keep(problem.gap_at(j, problem.relative_displacement(j, du)),
                   contact.reference_position(j).value_or(Point<dim>()));
    deepest = deepest.over_ranks(du.get_mpi_communicator());
    std::string places;
    // Penetrations at round-off of the length scale name no place.
    if (-deepest.value > 1e-12 * problem.length_scale)
      places = "the deepest penetration, " + Input::scientific(-deepest.value) +
               ", is at the node at " + deepest.place();
    const std::string law =
      problem.nonlinear != nullptr ? problem.nonlinear->worst_place(du) : "";
    if (!law.empty())
      places += (places.empty() ? "" : "; ") + law;
    return places;
  }

  template Residuals
  compute_residuals<2>(const IncrementalProblem<2> &,
                       const TrilinosWrappers::MPI::Vector &,
                       const TrilinosWrappers::MPI::Vector &,
                       const TrilinosWrappers::MPI::Vector &,
                       const std::vector<Tensor<1, 2>> &,
                       TrilinosWrappers::MPI::Vector &);
  template Residuals
  compute_residuals<3>(const IncrementalProblem<3> &,
                       const TrilinosWrappers::MPI::Vector &,
                       const TrilinosWrappers::MPI::Vector &,
                       const TrilinosWrappers::MPI::Vector &,
                       const std::vector<Tensor<1, 3>> &,
                       TrilinosWrappers::MPI::Vector &);
  template std::string
  worst_places<2>(const IncrementalProblem<2> &, const TrilinosWrappers::MPI::Vector &);
  template std::string
  worst_places<3>(const IncrementalProblem<3> &, const TrilinosWrappers::MPI::Vector &);
  template std::vector<double>
  contact_stiffness<2>(const IncrementalProblem<2> &, std::vector<double>);
  template std::vector<double>
  contact_stiffness<3>(const IncrementalProblem<3> &, std::vector<double>);
} // namespace FrictionalContact
