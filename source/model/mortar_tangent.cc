#include <frictional_contact/model/mortar_tangent.h>

namespace FrictionalContact
{
  void
  transform_to_basis(const TrilinosWrappers::SparseMatrix &basis,
                     const TrilinosWrappers::SparseMatrix &A,
                     TrilinosWrappers::SparseMatrix       &result)
  {
    TrilinosWrappers::SparseMatrix A_times_basis;
    A.mmult(A_times_basis, basis);
    basis.Tmmult(result, A_times_basis);
  }



  void
  MortarTangent::take(const TrilinosWrappers::SparseMatrix &new_tangent,
                      const bool                            make_entries)
  {
    tangent         = &new_tangent;
    entries_current = make_entries;
    if (make_entries)
      transform_to_basis(basis, *tangent, product);
  }



  void
  MortarTangent::vmult(Vector &dst, const Vector &src) const
  {
    Assert(tangent != nullptr, ExcInternalError());
    if (in_u.size() != src.size())
      {
        in_u.reinit(src, true);
        force_in_u.reinit(src, true);
      }
    basis.vmult(in_u, src);
    tangent->vmult(force_in_u, in_u);
    basis.Tvmult(dst, force_in_u);
    if (sliding != nullptr)
      sliding->Tvmult_add(dst, src);
    if (turning != nullptr)
      turning->vmult_add(dst, in_u);
  }



  double
  MortarTangent::diag_element(const types::global_dof_index i) const
  {
    return entries("its diagonal").diag_element(i);
  }



  std::vector<FullMatrix<double>>
  MortarTangent::blocks(const std::vector<std::vector<types::global_dof_index>> &nodes) const
  {
    return AssembledStiffness(entries("its node blocks")).blocks(nodes);
  }



  const TrilinosWrappers::SparseMatrix &
  MortarTangent::matrix(const std::string &purpose) const
  {
    return entries(purpose);
  }



  const TrilinosWrappers::SparseMatrix &
  MortarTangent::entries(const std::string &what) const
  {
    AssertThrow(entries_current,
                ExcMessage("The tangent in the contact pairs' basis changed within the "
                           "increment, and " + what + " was asked for; its entries are "
                           "made at the increment's start only."));
    return product;
  }
} // namespace FrictionalContact
