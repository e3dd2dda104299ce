#include <frictional_contact/solvers/contact_solver.h>

#include <iomanip>

namespace FrictionalContact
{
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
           << ", " << row.linear_iterations << " CG iterations" << std::defaultfloat
           << std::endl;
  }

  template class ContactSolver<2>;
  template class ContactSolver<3>;
} // namespace FrictionalContact
