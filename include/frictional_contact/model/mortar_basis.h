#pragma once

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <frictional_contact/solvers/stiffness_operator.h>
#include <frictional_contact/model/contact_operator.h>
#include <frictional_contact/model/elastic_body.h>
#include <frictional_contact/model/mortar_tangent.h>
#include <frictional_contact/model/pair_couplings.h>
#include <frictional_contact/solvers/volumetric_split.h>

#include <memory>
#include <vector>

namespace FrictionalContact
{
  /**
   * The change of basis u = Q w of Hueber and Wohlmuth that makes the
   * mortar contact conditions of two bodies node-local: Q = I + E, where E
   * holds P_jl in the rows of the slave dofs and the columns of the master
   * dofs, so that u_S = w_S + sum_l P_jl u_l and u = w elsewhere. In w, a
   * slave node's relative displacement n_j . (u_j - sum_l P_jl u_l) is its
   * own n_j . w_j, and the contact map of a rigid obstacle (one orthonormal
   * frame per node) serves both solvers unchanged, on K_w = Q^T K Q and
   * p_w = Q^T p. Master dofs held by hanging nodes are replaced by the dofs
   * they hang from; fixed and prescribed ones drop out (their increment is
   * in the lifting). Built anew at each increment, from the contact
   * operator's mortar rows, and within it where they change at every
   * Newton iterate. Owns Q, the transformed matrices and the Newton
   * tangent's terms of the moving geometry, H, G and F
   * (follow_reactions()).
   */
  template <int dim>
  class MortarBasis
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    /// Q from the mortar rows of @p contact (after update_pairs()), and
    /// K_w of the body's matrix as it is now unless @p with_stiffness is
    /// false: where no preconditioner is built from it and a nonlinear
    /// law's update_tangent() comes before any solve (K_w of a volumetric
    /// split is made either way).
    MortarBasis(const ElasticBody<dim>     &body,
                const ContactOperator<dim> &contact,
                const bool                  with_stiffness = true);

    /// K_w = Q^T K Q of the body's stiffness matrix, or of the tangent of
    /// nonlinear laws once update_tangent() made it.
    const StiffnessOperator &
    stiffness() const
    {
      Assert(has_tangent || has_stiffness, ExcInternalError());
      if (!has_tangent)
        return transformed_operator;
      if (tangent_itself)
        return *tangent_itself;
      return tangent_operator;
    }

    /// Q^T K Q of the body's stiffness matrix as it was when the basis was
    /// made: what preconditioners are built from (stiffness() changes with
    /// the tangent).
    const StiffnessOperator &
    initial_stiffness() const
    {
      Assert(has_stiffness, ExcInternalError());
      return transformed_operator;
    }

    /// K_T,w = Q^T K_T Q for the tangent @p tangent of nonlinear laws (by
    /// reference), as an operator (MortarTangent); from then on
    /// stiffness(). With @p make_entries (collective) also its entries,
    /// which the solvers' set-up at an increment's start reads. Where
    /// Q = I, @p tangent itself, which must be the body's matrix the basis
    /// was made from (not copied).
    void
    update_tangent(const TrilinosWrappers::SparseMatrix &tangent, const bool make_entries);

    /// The body's volumetric split in w (A_w = Q^T A Q, B_w = B Q), empty
    /// if the body has none.
    const VolumetricSplit &
    volumetric_split() const
    {
      return split;
    }

    /// p_w = Q^T p: a force in w (the work f . du is f_w . dw).
    void
    force_to_w(const Vector &force, Vector &force_w) const;

    /// f = Q^-T f_w = f_w - E^T f_w: the forces in u of forces in w.
    void
    force_to_u(const Vector &force_w, Vector &force) const;

    /// u = Q w.
    void
    displacement_to_u(const Vector &w, Vector &u) const;

    /// w = Q^-1 u = u - E u (E E = 0: no master dof is a slave dof).
    void
    displacement_to_w(const Vector &u, Vector &w) const;

    /**
     * The normal stiffness of the master body seen at each candidate of
     * @p contact that is a pair's slave node (infinity at the others, and
     * where Q = I): m_j = sum_l M_jl K_ll / A_l, the master's normal
     * stiffness per area at its nodes l (K_ll, its diagonal, or that of
     * the split's reduced stiffness; A_l = sum_j M_jl, the master's
     * lumped area on the interface) integrated against node j's mortar
     * weights (M = D P, D_jj the slave's lumped area). For matching meshes
     * of one material it is the slave's own stiffness. Collective.
     */
    std::vector<double>
    master_stiffness(const ElasticBody<dim> &body, const ContactOperator<dim> &contact) const;

    /// The rigid-body modes (locally owned vectors) in w, for the AMG.
    std::vector<std::vector<double>>
    modes_to_w(const std::vector<std::vector<double>> &modes) const;

    /**
     * Q anew from the mortar rows of @p contact as they are now (within an
     * increment, contact.mortar_rows_change_within_newton()); K_T,w
     * follows it (without entries). K_w stays as the basis was made
     * (preconditioners hold it). A vector in w is to be taken to u with
     * the old basis before, and back with the new one after.
     */
    void
    follow_rows(const ElasticBody<dim> &body, const ContactOperator<dim> &contact);

    /**
     * The Newton tangent's parts from the moving geometry (after
     * follow_rows()), for the reactions @p forces of the contact nodes
     * (Cartesian): they reach the master unknowns through P^T f_S, which
     * changes as a slave node slides by its relative displacement dw_j,
     * H^T dw = dP^T f_S to first order (the node's surroundings slide with
     * it); and the slave nodes' frames turn with the slave surface, which
     * at a slipping node turns the friction force and the normal reaction
     * into each other: F u, the force of the turning frame
     * (PairCouplings::turns()) at the node's own unknowns in
     * w, as for an obstacle's frames (the reactions keep their Cartesian
     * directions across a geometry; only the cone conditions see the
     * turn). Adds H^T + F Q to K_T,w. @p iterate (in w) is where the
     * geometry was taken: until the next one, the forces in w predict the
     * rows' change from there (add_geometry_change()), and the line
     * search turns the reactions along a step by frame_turns(), so that it
     * judges a step by the same model as the tangent.
     */
    void
    follow_reactions(const ElasticBody<dim>            &body,
                     const ContactOperator<dim>        &contact,
                     const std::vector<Tensor<1, dim>> &forces,
                     const Vector                      &iterate);

    /// @p force_w += @p sign H^T (@p w - the iterate where the geometry
    /// was taken): the first-order change of the reactions' master share
    /// between there and @p w (nothing without follow_reactions()).
    void
    add_geometry_change(const Vector &w, Vector &force_w, const double sign) const;

    /// The turn of each contact node's frame (ContactMap::normal_turns())
    /// for the step @p step (in w): G Q step at the nodes of @p contact,
    /// with G the turns of follow_reactions() (zero before).
    void
    frame_turns(const ContactOperator<dim>  &contact,
                const Vector                &step,
                std::vector<Tensor<1, dim>> &node_turns) const;

  private:
    /// Q from the mortar rows of @p contact; whether Q = I (no mortar
    /// row reaches a master's unknown).
    bool
    make_basis(const ElasticBody<dim> &body, const ContactOperator<dim> &contact);

    CouplingMatrix                 basis;
    /// H, the frames' turns G and their forces F of follow_reactions(),
    /// the iterate where they were made, and work vectors.
    CouplingMatrix                 sliding;
    CouplingMatrix                 turns;
    CouplingMatrix                 turning;
    Vector                         sliding_origin;
    mutable Vector                 slide, step_in_u, turn_of_step;
    TrilinosWrappers::SparseMatrix transformed_stiffness;
    TrilinosWrappers::SparseMatrix transformed_reduced_stiffness;
    AssembledStiffness             transformed_operator{transformed_stiffness};
    /// Whether transformed_stiffness holds K_w (the constructor's
    /// with_stiffness).
    bool                           has_stiffness = false;
    MortarTangent                  tangent_operator{basis.matrix};
    bool                           has_tangent = false;
    /// Where Q = I (no mortar row reaches a master dof: every master is a
    /// rigid tool), K_T,w is the tangent itself, made in the body's
    /// matrix; K_w is then K. Null otherwise.
    std::unique_ptr<AssembledStiffness> tangent_itself;
    TrilinosWrappers::SparseMatrix transformed_divergence;
    VolumetricSplit                split;
  };
} // namespace FrictionalContact
