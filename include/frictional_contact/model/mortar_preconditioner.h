#pragma once

#include <frictional_contact/model/mortar_basis.h>
#include <frictional_contact/solvers/spring_preconditioner.h>

namespace FrictionalContact
{
  /**
   * A preconditioner of K_w = Q^T K Q (contact pairs, MortarBasis) made
   * from one of K: Q^-1 M^-1 Q^-T, with M^-1 the geometric multigrid's
   * V-cycle of K. As K_w Q^-1 M^-1 Q^-T = Q^T (K M^-1) Q^-T is similar to
   * K M^-1, CG on K_w takes the iterations of CG on K. The Newton systems
   * K_w + S get the same cycle, without their springs: the springs as
   * they act in u (Q^-T S Q^-1, blocks that link each slave node to its
   * master nodes) made the cycle no better on ball_on_plate and worse in
   * tests/mortar_preconditioner.cc, as did the springs on the slave dofs
   * alone (doc/algorithm.md). Owns nothing: the cycle and the basis must
   * outlive it.
   */
  template <int dim>
  class MortarPreconditioner : public SpringPreconditioner
  {
  public:
    MortarPreconditioner(const SpringPreconditioner &of_u,
                         const MortarBasis<dim>     &basis)
      : of_u(of_u)
      , basis(basis)
    {}

    bool
    initialized() const override
    {
      return of_u.initialized();
    }

    /// Keeps the cycle of K (see above).
    void
    set_springs(const std::vector<NodalBlock> &) override
    {}

    /// dst = Q^-1 M^-1 Q^-T src.
    void
    vmult(Vector &dst, const Vector &src) const override;

  private:
    const SpringPreconditioner &of_u;
    const MortarBasis<dim>     &basis;
    mutable Vector              force, displacement;
  };
} // namespace FrictionalContact
