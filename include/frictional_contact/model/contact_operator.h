#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/trilinos_vector.h>

#include <frictional_contact/solvers/contact_map.h>
#include <frictional_contact/model/elastic_body.h>
#include <frictional_contact/model/mortar_interface.h>
#include <frictional_contact/model/rigid_tool.h>
#include <frictional_contact/solvers/friction_cone.h>
#include <frictional_contact/base/input.h>
#include <frictional_contact/base/time_function.h>
#include <frictional_contact/obstacle/interface.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <vector>

namespace FrictionalContact
{
  /**
   * The contact candidate nodes of this MPI rank and the paper's operators
   * on them. For candidate j (a vertex on a contact boundary that is not
   * fully fixed), the column block T_j = [t_n,j, T_t,j] of T maps the
   * local reaction r_j = (r_n, r_t) to nodal forces, and T_j^T maps a
   * displacement to its normal and tangential parts at the node. t_n,j is
   * the unit vector pointing into the obstacle (minus the obstacle's outward
   * normal), so that the gap after a displacement du is g_j - t_n,j^T du;
   * T_t,j holds dim-1 orthonormal tangents. Components held by a fixed
   * boundary are left out of T_j (they are not unknowns).
   *
   * Each candidate is owned by the rank owning its dofs, and only that rank
   * stores it: T and T^T act on locally owned vector entries only, without
   * communication.
   */
  template <int dim>
  class PairCouplings;

  template <int dim>
  class ContactOperator : public ContactMap<dim>
  {
    friend class PairCouplings<dim>;

  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    static void
    declare_parameters(ParameterHandler &prm);

    /// Reads the subsection "Contact" and creates the obstacle.
    ContactOperator(ParameterHandler &prm, const BoundaryNames &names);

    /// Whether the scene has a contact boundary or pair at all.
    bool
    active() const
    {
      return !contact_boundaries.empty() || !interfaces.empty();
    }

    /// Whether the scene has contact pairs of two bodies (mortar).
    bool
    has_pairs() const
    {
      return !interfaces.empty();
    }

    /**
     * Rebuilds the mortar data of every pair in the configuration X + u
     * (@p u_ghosted with ghost entries): the slave nodes' frames, areas and
     * gaps, and the rows P_jl; a rigid tool stands where it is at @p t_end.
     * Call at the start of every increment (from @p t_start to @p t_end),
     * with the displacement the increment starts from. With @p start
     * (ghosted), the data is that of X + u, the gaps those at X + start
     * measured with it: the increment from start solved again with the
     * geometry of where it ended. Collective.
     */
    void
    update_pairs(const ElasticBody<dim> &body,
                 const Vector           &u_ghosted,
                 const double            t_start,
                 const double            t_end,
                 const Vector           *start = nullptr);

    /// How far the last update_pairs() moved the slave nodes' data from
    /// the one before, on all ranks: the largest change of a unit normal
    /// and of a gap.
    struct PairChange
    {
      double normal = 0;
      double gap    = 0;
    };

    const PairChange &
    last_pair_change() const
    {
      return pair_change;
    }

    /// <Pair geometry>: when the passes of an increment solved again on
    /// the geometry where it ended (pairs that follow the configuration
    /// between solves, not within Newton) count as settled.
    struct PairPasses
    {
      /// The largest change of a unit normal, and of a gap over the
      /// largest displacement where the increment ended, that counts as
      /// settled.
      double       tolerance  = 1e-6;
      unsigned int max_passes = 20;
    };

    const PairPasses &
    pair_passes_settings() const
    {
      return pair_passes;
    }

    /// Whether a body at finite strain is on either side of a pair (the
    /// same on all ranks): its pairs' geometry moves within an increment.
    bool
    pairs_follow_configuration() const
    {
      return any_pair_follows;
    }

    /**
     * Whether the pairs' geometry is taken again at every Newton iterate
     * (update_pairs() with the increment's start): where a body at finite
     * strain is on a pair, in the tool's frames (pairs_take_tool_frames()),
     * or where <Geometry between bodies> asks for it for pairs of two
     * bodies, whose mortar rows then change within Newton
     * (mortar_rows_change_within_newton()).
     */
    bool
    pairs_follow_within_newton() const;

    /**
     * Whether the pairs within Newton take the tool's frames: every pair's
     * master is the rigid tool and <Rigid tool/Geometry at finite strain>
     * asks for it. The mortar rows then reach no unknown of a master
     * (MortarBasis is the identity).
     */
    bool
    pairs_take_tool_frames() const;

    /// Whether the rows P_jl of a pair with a deformable master are taken
    /// again at every Newton iterate: the basis u = Q w changes with them.
    bool
    mortar_rows_change_within_newton() const
    {
      return pairs_follow_within_newton() && !pairs_take_tool_frames();
    }

    /**
     * The prescribed tangential motion over the increment of what node j
     * touches, in its frame (component 0 is zero: the gap has the normal
     * part): for a candidate facing the obstacle, the obstacle's
     * @p obstacle_motion; for a slave node of a rigid tool, the tool's
     * motion there; 0 for a deformable master (its motion is unknown).
     * Where a pair's frame turned within the increment (update_pairs()
     * with a start), less the part of the slave node's offset from its
     * mortar point that the turn carries along: the slip is measured
     * objectively, zero under a rigid rotation of a stuck pair.
     */
    Tensor<1, dim>
    prescribed_slip(const unsigned int j, const Tensor<1, dim> &obstacle_motion) const
    {
      Tensor<1, dim> slip =
        to_local(j, nodes[j].pair < 0 ? obstacle_motion : pair_motions[j] - frame_slips[j]);
      slip[0] = 0;
      return slip;
    }

    /// The rigid tool (inactive if the scene has none).
    const RigidTool<dim> &
    rigid_tool() const
    {
      return *tool;
    }

    /**
     * The gap of candidate j at the start of an increment whose
     * displacement so far is @p start: from the obstacle's reference gap,
     * for a candidate that follows the configuration from its gap there
     * (follow_configuration()), or for a pair's slave node the mortar gap
     * of update_pairs(). Linear in @p start.
     */
    double
    gap_at_start(const unsigned int j, const Vector &start) const
    {
      if (nodes[j].pair >= 0)
        return pair_gaps[j];
      if (nodes[j].follows)
        return followed_gaps[j] -
               to_local(j, nodal_value(j, start) - followed_displacements[j])[0];
      return reference_gap(j) - local_part(j, start)[0];
    }

    /**
     * Whether some candidate of a body at finite strain faces the obstacle
     * (the same on all ranks): its gap and frame are then taken at the
     * deformed configuration (follow_configuration()), not linearised at
     * the reference one.
     */
    bool
    follows_configuration() const
    {
      return any_follows;
    }

    /**
     * Takes the gaps and frames of the candidates that follow the
     * configuration at X + @p u (a locally owned vector) against the
     * obstacle where it stands: the obstacle's normal and signed distance
     * there, linearised about @p u.
     */
    void
    follow_configuration(const Vector &u);

    /// Whether the contact geometry is taken again at Newton iterates: the
    /// obstacle's (follows_configuration()) or the pairs'
    /// (pairs_follow_within_newton()).
    bool
    geometry_follows_iterates() const
    {
      return follows_configuration() || pairs_follow_within_newton();
    }

    /**
     * Takes the geometry that follows the iterates at X + @p u (locally
     * owned) of an increment from @p t_start to @p t_end: the candidates'
     * that follow the configuration (follow_configuration()), and the
     * pairs' where it follows within Newton, their gaps measured at X +
     * @p start_ghosted (update_pairs()). Collective.
     */
    void
    follow_iterate(const ElasticBody<dim> &body,
                   const Vector           &u,
                   const double            t_start,
                   const double            t_end,
                   const Vector           &start_ghosted);

    bool
    frames_follow_configuration() const override
    {
      return any_follows || pairs_take_tool_frames();
    }

    /**
     * The turn of what each candidate touches, its outward normal, as the
     * configuration moves by @p u (to first order; fixed components left
     * out): the curvature of the obstacle, or of a pair's rigid tool where
     * the pairs' geometry follows within Newton, times the node's move;
     * zero elsewhere.
     */
    void
    normal_turns(const Vector &u, std::vector<Tensor<1, dim>> &turns) const override;

    /// f += turning_force(j, r_j, turn_j) at every candidate, for the
    /// turns of @p u (normal_turns()), fixed components left out.
    void
    add_frame_stiffness(const std::vector<Tensor<1, dim>> &r,
                        const Vector                      &u,
                        Vector                            &f) const override;

    Tensor<1, dim>
    frame_turn(const unsigned int    j,
               const Tensor<1, dim> &r_j,
               const Tensor<1, dim> &turn) const override
    {
      return to_local(j, turning_force(j, r_j, turn));
    }

    void
    add_force_beyond_frames(const std::vector<Tensor<1, dim>> &r,
                            const std::vector<Tensor<1, dim>> &turns,
                            const double                       scale,
                            Vector                            &f) const override;

    /// How candidate j's gap changes as it slides along a deformable
    /// master, in its frame (MortarInterface::SlaveNode::gap_slope); zero
    /// for any other candidate.
    Tensor<1, dim>
    gap_slope(const unsigned int j) const;

    /**
     * Finds the candidates of @p body on the contact boundaries and builds
     * their frames for the obstacle at its initial position. Throws an
     * InputError if a contact boundary has no candidate.
     */
    void
    setup(const ElasticBody<dim> &body, const BoundaryNames &names);

    /// The obstacle's prescribed rigid displacement at time @p t.
    Tensor<1, dim>
    obstacle_displacement(const double t) const;

    /**
     * Moves the obstacle rigidly by @p displacement (from its position in
     * the parameter file) and rebuilds the frames there: the normal of
     * candidate j is the obstacle's at x_j - displacement.
     */
    void
    move_obstacle(const Tensor<1, dim> &displacement);

    /**
     * The deepest penetration into the obstacle (at its current position)
     * of any vertex on a contact boundary, candidate or not (hanging nodes,
     * fixed nodes), for the displacement @p u_ghosted (with ghost entries);
     * 0 if none penetrates. Collective.
     */
    double
    deepest_boundary_penetration(const ElasticBody<dim> &body,
                                 const Vector           &u_ghosted) const;

    /// Signed distance from the reference position of j to the obstacle.
    double
    reference_gap(const unsigned int j) const
    {
      return obstacle->signed_distance(nodes[j].position - obstacle_shift);
    }

    /// The obstacle's rigid displacement as move_obstacle() last set it.
    const Tensor<1, dim> &
    obstacle_position() const
    {
      return obstacle_shift;
    }

    /// Number of candidates on this rank.
    unsigned int
    n_local() const override
    {
      return nodes.size();
    }

    /// Number of candidates on all ranks (the paper's c).
    types::global_dof_index
    n_candidates() const override
    {
      return n_global;
    }

    /// The Cartesian components of the (non-ghosted) vector @p u at node j.
    Tensor<1, dim>
    nodal_value(const unsigned int j, const Vector &u) const
    {
      const double  *values = u.begin();
      Tensor<1, dim> u_j;
      for (unsigned int c = 0; c < dim; ++c)
        u_j[c] = values[nodes[j].local_dofs[c]];
      return u_j;
    }

    /// T_j^T u: normal part (component 0) and tangential parts of @p u at j.
    Tensor<1, dim>
    local_part(const unsigned int j, const Vector &u) const override
    {
      return to_local(j, nodal_value(j, u));
    }

    /// (t_n^T v, t_1^T v, ...) for a Cartesian vector @p v at node j; the
    /// components held by fixed boundaries are ignored.
    Tensor<1, dim>
    to_local(const unsigned int j, Tensor<1, dim> v) const;

    /// Adds the Cartesian vector @p value to the entries of node j in @p f.
    void
    add_nodal_value(const unsigned int j, const Tensor<1, dim> &value, Vector &f) const
    {
      double *entries = f.begin();
      for (unsigned int c = 0; c < dim; ++c)
        entries[nodes[j].local_dofs[c]] += value[c];
    }

    /// f = the Cartesian nodal @p values at the candidates, zero elsewhere.
    void
    set_nodal_values(const std::vector<Tensor<1, dim>> &values, Vector &f) const;

    /// f = T r for the reactions @p r of the local candidates.
    void
    apply(const std::vector<Tensor<1, dim>> &r, Vector &f) const override;

    /**
     * The nodal forces of the reactions @p r on both sides of every pair:
     * T r at the candidates (a pair's slave nodes, and those facing the
     * obstacle), and -sum_j P_jl F_j r_j at the master nodes (the forces
     * the slave side transfers, M^T lambda). @p f is a locally owned
     * vector; collective.
     */
    void
    forces_on_both_sides(const std::vector<Tensor<1, dim>> &r, Vector &f) const;

    /// f += T_j r_j.
    void
    add_reaction(const unsigned int    j,
                 const Tensor<1, dim> &r_j,
                 Vector               &f) const override
    {
      add_nodal_value(j, to_cartesian(j, r_j), f);
    }

    /// c_j = t_n,j^T K_jj t_n,j for each local candidate: the stiffness of
    /// node j in the normal direction (force/length), a scale of K that
    /// follows the units of the problem.
    std::vector<double>
    normal_stiffness(const StiffnessOperator &K) const override;

    /// T_j B T_j^T on the dim dofs of node j.
    bool
    nodal_block(const unsigned int    j,
                const Tensor<2, dim> &B,
                NodalBlock           &block) const override;

    /// The largest singular value of T, computed from the nodal blocks.
    double
    largest_singular_value() const override;

    /// max_j |T_j^T T_j - I| (0 for orthonormal frames on unfixed nodes).
    double
    orthonormality_defect() const;

    /// The bodies that contact may hold: those with a vertex on a contact
    /// boundary (facing the obstacle) or on either side of a pair (after
    /// setup(); the same on all ranks).
    const std::set<types::material_id> &
    bodies_facing_contact() const
    {
      return facing_contact;
    }

    /// The bodies candidate j holds where it is in contact: its own, and
    /// for a pair's slave node the master's bodies.
    std::set<types::material_id>
    bodies_held_by(const unsigned int j) const;

    /// Whether candidate j is a slave node of a pair of two bodies (not
    /// facing the obstacle or a tool): its force acts between the bodies
    /// and adds nothing to the whole.
    bool
    acts_between_bodies(const unsigned int j) const
    {
      return nodes[j].pair >= 0 && !interfaces[nodes[j].pair].has_rigid_master();
    }

    /// Global index of the x-displacement dof of candidate j.
    types::global_dof_index
    first_dof(const unsigned int j) const
    {
      return nodes[j].dofs[0];
    }

    /// Global index of displacement component @p c of candidate j.
    types::global_dof_index
    dof(const unsigned int j, const unsigned int c) const
    {
      return nodes[j].dofs[c];
    }

    /// Signed distance from @p point to the obstacle (> 0 outside).
    double
    distance_to_obstacle(const Point<dim> &point) const
    {
      return obstacle->signed_distance(point);
    }

    std::optional<Point<dim>>
    reference_position(const unsigned int j) const override
    {
      return nodes[j].position;
    }

    /**
     * The lumped area of candidate j (length in 2D): the integral over the
     * contact boundary faces of the node's Q1 shape function. The contact
     * pressure of the node is its normal reaction divided by this area.
     */
    double
    nodal_area(const unsigned int j) const
    {
      return nodes[j].area;
    }

    /// The vector x with components x_c = sum_k T_j(c,k) v_k at node j.
    Tensor<1, dim>
    to_cartesian(const unsigned int j, const Tensor<1, dim> &v) const;

    /// The obstacle's cone for its candidates, the pair's for its slave nodes.
    const FrictionCone<dim> &
    friction_cone(const unsigned int j) const override
    {
      return cones[nodes[j].pair + 1];
    }

    double
    largest_friction_coefficient() const override
    {
      // The obstacle's coefficient counts only if the scene has an obstacle.
      double largest = contact_boundaries.empty() ? 0. : cones[0].mu;
      for (unsigned int k = 1; k < cones.size(); ++k)
        largest = std::max(largest, cones[k].mu);
      return largest;
    }

    /// Whether the obstacle or any pair has friction (then T has tangents).
    bool
    has_friction() const
    {
      return largest_friction_coefficient() > 0;
    }

    /// Bytes held for the candidates (frames, dofs).
    std::size_t
    memory_consumption() const;

    /// "frictionless (...)", "frictional (mu = 0.3)", or with pairs of
    /// their own coefficients "frictional (mu = 0.3; 0.5 on 'a : b')".
    std::string
    describe_friction(const BoundaryNames &names) const;

    /// "slave : master" of pair @p k (the tool's name for a tool).
    std::string
    pair_name(const unsigned int k, const BoundaryNames &names) const;

    /// "bottom" or "bottom, top"
    std::string
    describe_boundaries(const BoundaryNames &names) const;

  private:
    /**
     * At a node whose frame turns, the change of its contact force T_j r_j
     * (@p r_j held, in its frame) as the outward normal n of what it
     * touches turns by @p turn (Cartesian; t_n = -n, so dt_n = -turn; for
     * an obstacle turn = G_j move, G_j the gradient of its outward normal)
     * with the tangents carried along (dt_k = (t_k . turn) t_n, the least
     * rotation, as turn_tangents() turns them): r_n turn - (f_t . turn)
     * t_n, f_t = sum_k r_k t_k the tangential reaction: the normal part
     * turns into the tangent and the friction force into the normal.
     */
    Tensor<1, dim>
    turning_force(const unsigned int    j,
                  const Tensor<1, dim> &r_j,
                  const Tensor<1, dim> &turn) const;

    /// @p v without the components that fixed boundaries hold at node j.
    Tensor<1, dim>
    free_part(const unsigned int j, Tensor<1, dim> v) const;

    /// Turns candidate j's tangents with its normal, now @p into, by the
    /// least rotation (continuous, so that the tangential reactions keep
    /// their meaning).
    void
    turn_tangents(const unsigned int j, const Tensor<1, dim> &into);

    struct Node
    {
      Point<dim> position;
      /// Global indices of the displacement components.
      std::array<types::global_dof_index, dim> dofs;
      /// Index of each displacement component in the locally owned range.
      std::array<unsigned int, dim> local_dofs;
      /// Whether the component is an unknown (not held by a fixed boundary).
      std::array<bool, dim> free;
      /// Whether the node's gap and frame follow the configuration (a node
      /// of a finite-strain body facing the obstacle).
      bool follows = false;
      /// The pair whose slave node this is (-1: a candidate facing the
      /// obstacle); small, to sit in the padding after free.
      std::int16_t pair = -1;
      /// The body of the node's cells, as its index in body_ids; small, to
      /// sit in the padding too.
      std::uint16_t body = 0;
      /// t_n,j: unit vector pointing into the obstacle.
      Tensor<1, dim> into_obstacle;
      /// Lumped area on the contact boundaries (see nodal_area()); for a
      /// pair's slave node its mortar weight D_jj.
      double area = 0;
    };

    /// The candidates on @p boundaries into @p found (their pair @p pair,
    /// -1 for the obstacle's); returns the boundaries that have candidates
    /// on any rank. Collective.
    std::set<types::boundary_id>
    find_candidates(const ElasticBody<dim>                  &body,
                    const std::set<types::boundary_id>      &boundaries,
                    const int                                pair,
                    std::map<types::global_dof_index, Node> &found) const;

    /// Throws an InputError if the obstacle or another body starts inside
    /// a body. Collective.
    void
    check_initial_gaps(const ElasticBody<dim> &body);

    /// The obstacle's friction cone, then one per pair (in <Contact/Pairs>'s order).
    std::vector<FrictionCone<dim>>               cones;
    /// <Contact/Interference fit>: the pairs' bodies may overlap at the
    /// start.
    bool interference_fit = false;
    std::set<types::boundary_id>                 contact_boundaries;
    /// See bodies_facing_contact().
    std::set<types::material_id>                 facing_contact;
    /// The material ids of the bodies, in the order Node::body counts.
    std::vector<types::material_id>              body_ids;
    /// The pairs of two bodies (<Contact/Pairs>), and the gap of each
    /// candidate that is a pair's slave node (empty without pairs).
    std::vector<MortarInterface<dim>>            interfaces;
    std::vector<double>                          pair_gaps;
    /// The rigid tool's motion over the increment at each of its slave
    /// nodes, Cartesian (zero elsewhere).
    std::vector<Tensor<1, dim>>                  pair_motions;
    /// Each slave node's normal where its increment started (the last
    /// update_pairs() without a start), and the tangential motion that
    /// the turn from it to the current normal gives the node's offset
    /// from its mortar point (zero while the frame has not turned).
    std::vector<Tensor<1, dim>>                  start_normals;
    std::vector<Tensor<1, dim>>                  frame_slips;
    std::unique_ptr<RigidTool<dim>>              tool;
    std::unique_ptr<Obstacle::Interface<dim>>    obstacle;
    std::vector<Node>                            nodes;
    /// T_t,j; empty without friction (the tangential operator is not needed).
    std::vector<std::array<Tensor<1, dim>, dim - 1>> tangents;
    /// For the candidates that follow the configuration: the gap and the
    /// displacement of the last follow_configuration() (0 elsewhere).
    std::vector<double>                          followed_gaps;
    std::vector<Tensor<1, dim>>                  followed_displacements;
    /// The gradient of the outward normal of what the node touches there
    /// (the obstacle's, or the tool's where the pairs take its frames).
    std::vector<Tensor<2, dim>>                  normal_gradients;
    /// For each pair's slave node, the length of its unit normal with the
    /// fixed components left out (1 where none is fixed): the scale of its
    /// frame's turn.
    std::vector<double>                          pair_normal_lengths;
    /// The turns of add_frame_stiffness().
    mutable std::vector<Tensor<1, dim>>          turns_scratch;
    bool                                         any_follows = false;
    bool                                         any_pair_follows = false;
    /// <Geometry between bodies> is every Newton iterate.
    bool                                         bodies_every_newton_iterate = false;
    PairPasses                                   pair_passes;
    PairChange                                   pair_change;
    std::unique_ptr<TimeFunction>                rigid_displacement;
    Tensor<1, dim>                               obstacle_shift;
    types::global_dof_index                      n_global = 0;
    MPI_Comm                                     mpi_communicator = MPI_COMM_WORLD;
  };
} // namespace FrictionalContact
