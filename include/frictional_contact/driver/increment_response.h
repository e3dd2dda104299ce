#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <frictional_contact/model/model.h>
#include <frictional_contact/model/mortar_basis.h>
#include <frictional_contact/solvers/nonlinear_stiffness.h>

namespace FrictionalContact
{
  /**
   * The internal force of the model's nonlinear laws over one increment, as
   * the solvers see it (NonlinearStiffness): N(du) = f_int(u_0 + du) -
   * f_0 from the configuration u_0 the increment starts from (u^l with the
   * prescribed increment), its held and hanging dofs completed by the
   * constraints, f_0 the linearisation of f_int(u_0) at u^l; in the basis
   * w of contact pairs, N_w(dw) = Q^T N(Q dw) and the tangent Q^T K_T Q.
   * Owns u_0, f_0 and the vectors of the evaluations.
   */
  template <int dim>
  class IncrementResponse : public NonlinearStiffness
  {
  public:
    /**
     * A linearised start: the
     * increment starts from u_0 = u^l + @p lifting, the prescribed
     * increment, which alone squashes the cells beside the moved boundary
     * far from equilibrium (and, with a plastic law, flows them). Instead
     * of f_int(u_0), the reference force is
     * its linearisation at u^l, f_int(u^l) + K_T(u^l) lifting (the
     * directional derivative by a difference quotient), and until the
     * first evaluation with the tangent N(du) is linear, K_T(u^l) du: the
     * first Newton step is that of the linearisation at u^l with the
     * prescribed increment as its constraint. The force balance is that of
     * f_int(u_0 + du) throughout. @p mortar: the increment's basis of
     * contact pairs (nullptr without).
     */
    IncrementResponse(Model<dim>       &model,
                      MortarBasis<dim> *mortar,
                      const Vector     &start,
                      const Vector     &lifting);

    /// The reference force, the linearisation of f_int(u_0) at u^l, in u.
    const Vector &
    start_force() const
    {
      return force_at_start;
    }

    void
    internal_force_change(const Vector &du, Vector &dst, const bool with_tangent) override;

    types::global_dof_index
    plastic_points() const override
    {
      return plastic;
    }

    double
    force_scale() const override
    {
      return scale;
    }

    /// For laws with history (plasticity).
    bool
    preconditioner_from_start() const override
    {
      return model.get_history().active();
    }

    /// The smallest det F at u_0 + @p du and its cell (finite strain).
    std::string
    worst_place(const Vector &du) override;

  private:
    /// du_in_u = @p du (in the pairs' basis w, if any) in u.
    void
    take_in_u(const Vector &du);

    /// u (and u_ghosted) = u_0 + @p du_in_u.
    void
    move_to(const Vector &du_in_u);

    /// f_int(u) into force for u = u_0 + @p du_in_u (the tangent too if
    /// asked).
    void
    evaluate(const Vector &du_in_u, const bool with_tangent);

    Model<dim>             &model;
    MortarBasis<dim>       *mortar;
    const Vector            start;
    Vector                  force_at_start, u, u_ghosted, force, du_in_u;
    types::global_dof_index plastic = 0;
    double                  scale   = 0;
    /// Whether N is still linear (before the first evaluation with the
    /// tangent).
    bool linear = true;
  };
} // namespace FrictionalContact
