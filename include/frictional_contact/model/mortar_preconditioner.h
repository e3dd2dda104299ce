#pragma once

#include <frictional_contact/model/mortar_basis.h>
#include <frictional_contact/solvers/spring_preconditioner.h>

namespace FrictionalContact
{
  /**
   * A preconditioner of K_w = Q^T K Q (contact pairs, MortarBasis) made
   * from one of K: Q^-1 M^-1 Q^-T, with M^-1 the geometric multigrid's
   * V-cycle of K. As K_w Q^-1 M^-1 Q^-T = Q^T (K M^-1) Q^-T is similar to
   * K M^-1, CG on K_w takes the iterations of CG on K. With springs S at
   * the slave nodes (the Newton systems, K_w + S = Q^T (K + Q^-T S Q^-1) Q),
   * the cycle of K gets each spring as Q^-T S Q^-1 acts in u
   * (MortarBasis::spring_to_u): a block on the slave node's dofs and the
   * master dofs of its mortar rows, which holds the slave node against the
   * master surface. Owns nothing: the cycle and the basis must outlive it.
   */
  template <int dim>
  class MortarPreconditioner : public SpringPreconditioner
  {
  public:
    MortarPreconditioner(SpringPreconditioner   &of_u,
                         const MortarBasis<dim> &basis)
      : of_u(of_u)
      , basis(basis)
    {}

    bool
    initialized() const override
    {
      return of_u.initialized();
    }

    /// The springs, as they act in u, to the cycle of K.
    void
    set_springs(const std::vector<NodalBlock> &springs) override;

    /// dst = Q^-1 M^-1 Q^-T src.
    void
    vmult(Vector &dst, const Vector &src) const override;

  private:
    SpringPreconditioner   &of_u;
    const MortarBasis<dim> &basis;
    mutable Vector          force, displacement;
  };
} // namespace FrictionalContact
