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

  template <int dim>
  void
  MortarPreconditioner<dim>::set_springs(const std::vector<NodalBlock> &springs)
  {
    std::vector<NodalBlock> in_u;
    in_u.reserve(springs.size());
    for (const NodalBlock &spring : springs)
      in_u.push_back(basis.spring_to_u(spring));
    of_u.set_springs(in_u);
  }



  template class MortarPreconditioner<2>;
  template class MortarPreconditioner<3>;
} // namespace FrictionalContact
