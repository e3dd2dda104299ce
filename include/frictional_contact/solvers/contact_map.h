#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <frictional_contact/solvers/stiffness_operator.h>
#include <frictional_contact/solvers/friction_cone.h>
#include <frictional_contact/solvers/nodal_block.h>

#include <numeric>
#include <optional>
#include <vector>

namespace FrictionalContact
{
  /**
   * The paper's operator T between displacements and the local contact
   * coordinates of the candidates, with the friction cone: what the
   * accelerated primal-dual method needs of a contact problem. Candidate j
   * has dim columns T_j = [t_n,j, T_t,j] of T; T r = sum_j T_j r_j are the
   * nodal forces of the reactions r, and T_j^T u the normal and tangential
   * parts of a displacement u at j. The semismooth Newton method also
   * needs the T_j to be orthonormal on disjoint entries (as ContactOperator's
   * frames are), so that v - T_j T_j^T v removes the part of v at j. The candidates of an MPI rank touch only
   * its locally owned vector entries.
   *
   * ContactOperator builds T from a mesh and an obstacle (one node per
   * candidate, orthonormal frames); SparseContactMap holds a general sparse
   * T read from an FCLIB file.
   */
  template <int dim>
  class ContactMap
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    virtual ~ContactMap() = default;

    /// Number of candidates on this rank.
    virtual unsigned int
    n_local() const = 0;

    /// Number of candidates on all ranks (the paper's c).
    virtual types::global_dof_index
    n_candidates() const = 0;

    /// T_j^T u: normal part (component 0) and tangential parts of @p u at j.
    virtual Tensor<1, dim>
    local_part(const unsigned int j, const Vector &u) const = 0;

    /// Where candidate j is in the reference configuration, to name it in
    /// a message; nothing for candidates without a place (the contacts of
    /// an FCLIB problem).
    virtual std::optional<Point<dim>>
    reference_position(const unsigned int /*j*/) const
    {
      return std::nullopt;
    }

    /// f = T r for the reactions @p r of the local candidates.
    virtual void
    apply(const std::vector<Tensor<1, dim>> &r, Vector &f) const = 0;

    /// f += T_j r_j: the nodal forces of the reaction @p r_j of candidate j.
    virtual void
    add_reaction(const unsigned int    j,
                 const Tensor<1, dim> &r_j,
                 Vector               &f) const = 0;

    /// c_j = t_n,j^T K t_n,j for each local candidate: the stiffness of
    /// candidate j in the normal direction, a scale of K that follows the
    /// units of the problem.
    virtual std::vector<double>
    normal_stiffness(const StiffnessOperator &K) const = 0;

    /**
     * T_j B T_j^T on the dofs of candidate j's node, for a block @p B in
     * its local coordinates (normal first): how a preconditioner sees a
     * spring in the directions of a node condition. Returns false, and
     * leaves @p block alone, if T_j does not act on the dofs of one node
     * (the default).
     */
    virtual bool
    nodal_block(const unsigned int /*j*/,
                const Tensor<2, dim> & /*B*/,
                NodalBlock & /*block*/) const
    {
      return false;
    }

    /**
     * Whether the frames follow the configuration (T = T(x), finite
     * strain against a curved obstacle): the Newton tangent then has the
     * stiffness of the turning frames, add_frame_stiffness().
     */
    virtual bool
    frames_follow_configuration() const
    {
      return false;
    }

    /**
     * The turn of each candidate's frame as the configuration moves by
     * @p u, to first order: the change of the outward normal of what it
     * touches (t_n turns by minus it), Cartesian; zero for fixed frames.
     */
    virtual void
    normal_turns(const Vector & /*u*/, std::vector<Tensor<1, dim>> &turns) const
    {
      turns.assign(n_local(), Tensor<1, dim>());
    }

    /**
     * f += the change of the contact forces T_j r_j, the reactions @p r
     * (in their frames) held, as the configuration moves by @p u and the
     * frames turn with it (normal_turns(); nothing for fixed frames).
     * Collective.
     */
    virtual void
    add_frame_stiffness(const std::vector<Tensor<1, dim>> & /*r*/,
                        const Vector & /*u*/,
                        Vector & /*f*/) const
    {}

    /**
     * The change of candidate j's reaction @p r_j, in its frame, as its
     * frame turns by @p turn (a turn of normal_turns()), the contact force
     * held: the part of add_frame_stiffness() at j (zero for fixed frames).
     */
    virtual Tensor<1, dim>
    frame_turn(const unsigned int /*j*/,
               const Tensor<1, dim> & /*r_j*/,
               const Tensor<1, dim> & /*turn*/) const
    {
      return {};
    }

    /**
     * f += the part of the turning frames' force (add_frame_stiffness(),
     * the reactions @p r held, each frame turned by @p scale times its
     * turn @p turns[j]) that the frames cannot carry as a change of their
     * reactions (frame_turn()): none where a frame spans every free
     * direction, the whole force where it has a normal alone (no
     * friction), at the nodes that face an obstacle or the rigid tool in
     * its frames. Taking the geometry
     * again at the turned configuration turns that part of the force with
     * the frame, while the rest of it stays Cartesian. Nothing for fixed
     * frames.
     */
    virtual void
    add_force_beyond_frames(const std::vector<Tensor<1, dim>> & /*r*/,
                            const std::vector<Tensor<1, dim>> & /*turns*/,
                            const double /*scale*/,
                            Vector & /*f*/) const
    {}

    /// The largest singular value of T (the paper's sigma_T).
    virtual double
    largest_singular_value() const = 0;

    /// The friction cone of candidate j (each contact pair may have its
    /// own coefficient).
    virtual const FrictionCone<dim> &
    friction_cone(const unsigned int j) const = 0;

    double
    friction_coefficient(const unsigned int j) const
    {
      return friction_cone(j).mu;
    }

    /// The largest friction coefficient of any candidate on any rank (0:
    /// frictionless everywhere).
    virtual double
    largest_friction_coefficient() const = 0;
  };

  /// The mean over all candidates of @p local_values, one value per local
  /// candidate of @p contact (such as its normal_stiffness()). Collective.
  template <int dim>
  double
  mean_over_candidates(const ContactMap<dim>     &contact,
                       const std::vector<double> &local_values,
                       const MPI_Comm             comm)
  {
    const double sum =
      std::accumulate(local_values.begin(), local_values.end(), 0.);
    return Utilities::MPI::sum(sum, comm) /
           std::max<double>(1, contact.n_candidates());
  }
} // namespace FrictionalContact
