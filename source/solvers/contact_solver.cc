#include <frictional_contact/base/input.h>
#include <frictional_contact/solvers/contact_solver.h>

#include <iomanip>

namespace FrictionalContact
{
  void
  StoppingRule::declare_parameters(ParameterHandler  &prm,
                                   const std::string &default_tolerance,
                                   const std::string &tolerance_text,
                                   const std::string &default_max_iterations,
                                   const std::string &max_iterations_text)
  {
    prm.declare_entry("Tolerance",
                      default_tolerance,
                      Patterns::Double(0.),
                      tolerance_text);
    prm.declare_entry("Maximum iterations",
                      default_max_iterations,
                      Patterns::Integer(1),
                      max_iterations_text);
  }



  void
  StoppingRule::parse_parameters(ParameterHandler  &prm,
                                 const std::string &subsection)
  {
    tolerance      = prm.get_double("Tolerance");
    max_iterations = prm.get_integer("Maximum iterations");
    if (!(tolerance > 0))
      Input::fail("Contact solver/" + subsection + "/Tolerance",
                  Input::to_text(tolerance),
                  "a positive number is expected (an error of exactly 0 is "
                  "never reached in floating point)");
  }



  template <int dim>
  void
  ContactSolver<dim>::report(const unsigned int k, const HistoryRow &row) const
  {
    if (pcout == nullptr || report_every == 0 || k % report_every != 0)
      return;
    *pcout << "    iteration " << std::setw(6) << k << ": step "
           << std::setprecision(3) << std::scientific << row.step
           << ", residuals " << row.residuals.force_balance << ' '
           << row.residuals.complementarity << ' ' << row.residuals.penetration
           << ", " << row.linear_iterations << " Krylov iterations";
    if (row.forcing_term > 0)
      *pcout << " (forcing term " << row.forcing_term << "), "
             << row.active_set_changes << " set changes";
    *pcout << std::defaultfloat << std::endl;
  }

  template class ContactSolver<2>;
  template class ContactSolver<3>;
} // namespace FrictionalContact
