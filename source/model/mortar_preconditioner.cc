#include <frictional_contact/model/mortar_preconditioner.h>

namespace FrictionalContact
{
  template <int dim>
  void
  MortarPreconditioner<dim>::vmult(Vector &dst, const Vector &src) const
  {
    if (force.size() != src.size())
      {
        force.reinit(src, true);
        displacement.reinit(src, true);
      }
    basis.force_to_u(src, force);
    of_u.vmult(displacement, force);
    basis.displacement_to_w(displacement, dst);
  }

  template class MortarPreconditioner<2>;
  template class MortarPreconditioner<3>;
} // namespace FrictionalContact
