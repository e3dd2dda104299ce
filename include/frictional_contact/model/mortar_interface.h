#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/trilinos_vector.h>

#include <frictional_contact/model/elastic_body.h>
#include <frictional_contact/model/mortar_segments.h>
#include <frictional_contact/model/rigid_tool.h>

#include <array>
#include <map>
#include <set>
#include <vector>

namespace FrictionalContact
{
  /**
   * One contact pair of two deformable bodies: a slave boundary, which
   * carries the Lagrange multipliers (dual basis, so one multiplier and one
   * friction cone per slave node), and a master boundary. Owns the faces of
   * both sides and, after update(), the mortar data of each locally owned
   * slave vertex in the current configuration: the averaged outward normal,
   * the weight D_jj, the row P_jl = M_jl / D_jj that maps master
   * displacements to the slave node, and the nodal gap
   * sum_l P_jl n_j . (y_l - x_j). At small strain the data is that of
   * where the increment starts; at finite strain it is taken again at
   * every Newton iterate, or where each solve ended
   * (solve_with_settled_pair_geometry()), as <Contact/Geometry between
   * bodies> says. Master faces may live on any rank: their current
   * vertices are gathered on every rank at each update. The master may
   * also be a rigid tool, whose faces every rank knows and whose
   * displacement is given: then the rows P_jl have no unknowns, and each
   * slave node keeps the tool's motion over the increment instead.
   */
  template <int dim>
  class MortarInterface
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;
    using NodeDofs = std::array<types::global_dof_index, dim>;

    /// A pair of two boundaries of the mesh, or with @p tool (then
    /// @p master is not used) a boundary against a rigid tool.
    MortarInterface(const types::boundary_id slave,
                    const types::boundary_id master,
                    const RigidTool<dim>    *tool = nullptr);

    /// Collects the faces of both boundaries on the current mesh.
    void
    setup(const ElasticBody<dim> &body);

    /**
     * Computes the mortar data of the locally owned slave vertices in the
     * configuration X + u, @p u_ghosted with ghost entries, for the
     * increment from @p t_start to @p t_end (a rigid tool stands where it
     * is at @p t_end). With @p gaps_at (ghosted too), the gaps are those
     * of the slave and master vertices displaced by it, measured with the
     * normals and rows of X + u: the gaps at the start of an increment
     * whose geometry is taken where it ends. Collective.
     */
    void
    update(const ElasticBody<dim> &body,
           const Vector           &u_ghosted,
           const double            t_start,
           const double            t_end,
           const Vector           *gaps_at = nullptr);

    /**
     * Whether a rigid master gives the slave nodes their frames: the
     * normal is then the tool's own (its vertex normals integrated against
     * the node's dual function, as its points are) instead of the slave
     * surface's, so that the gap is measured as a distance to the tool
     * and turns with the tool's curvature as the node slides, as against
     * an obstacle (for a body at finite strain, whose geometry is taken at
     * every Newton iterate).
     */
    void
    take_tool_frames(const bool take)
    {
      tool_frames = take && tool != nullptr;
    }

    /// Whether the master is a rigid tool.
    bool
    has_rigid_master() const
    {
      return tool != nullptr;
    }

    /// The mortar data of a slave vertex.
    struct SlaveNode
    {
      /// The averaged outward unit normal of the slave surface; with the
      /// tool's frames (take_tool_frames()), minus the tool's normal at
      /// the node's mortar point.
      Tensor<1, dim> normal;
      /// With the tool's frames: the gradient of the tool's outward unit
      /// normal at the mortar point, which moves with the node (dn = G du).
      Tensor<2, dim> normal_gradient;
      /// D_jj: the integral of the node's dual function over the part of
      /// the slave surface the master covers (0 if none).
      double weight = 0;
      /// The integral of the node's Q1 function over the slave faces.
      double full_weight = 0;
      /// The nodal gap to the master (length), if the node has a master.
      double gap = 0;
      /// The master's mortar point minus the node where the gaps are
      /// measured, sum_l P_jl (y_l - x_j) (a rigid master where it stood
      /// at t_start); its normal part is the gap of a deformable master.
      Tensor<1, dim> offset;
      /// The master vertices and P_jl (none for a rigid tool).
      std::vector<std::pair<NodeDofs, double>> masters;
      /// How each P_jl changes as the node slides along the master by
      /// delta (its surroundings with it): dP_jl = master_slides[l] . delta,
      /// in the order of masters.
      std::vector<Tensor<1, dim>> master_slides;
      /// How the gap changes as the node slides by delta (its master
      /// where it is now): dg = gap_slope . delta, sum_l
      /// master_slides[l] (n . (y_l - x_j)); zero for a rigid tool.
      Tensor<1, dim> gap_slope;
      /// Where the rows follow the Newton iterates (a deformable master):
      /// how the normal turns as the vertices of the node's slave faces
      /// move, dn = sum_k D_k dx_k, one D_k per vertex k (the node among
      /// them; a hanging vertex's share of the normal left out).
      std::vector<std::pair<NodeDofs, Tensor<2, dim>>> normal_derivatives;
      /// The master's displacement over the increment at the node,
      /// sum_l P_jl (y_l(t_end) - y_l(t_start)): a rigid tool's motion; 0
      /// for a deformable master, whose motion is unknown.
      Tensor<1, dim> master_motion;
    };

    /// The data of the locally owned slave vertex whose x dof is @p dof,
    /// or nullptr if it is not one.
    const SlaveNode *
    node(const types::global_dof_index dof) const;

    /// The slave vertices of this rank (keyed by their x dof).
    const std::map<types::global_dof_index, SlaveNode> &
    slave_nodes() const
    {
      return nodes;
    }

    types::boundary_id
    slave_boundary() const
    {
      return slave_id;
    }

    types::boundary_id
    master_boundary() const
    {
      return master_id;
    }

    /**
     * Calls @p add(dof, weight) for the unknowns a master displacement dof
     * stands for: itself if it is free, the dofs it hangs from with their
     * weights if it is a hanging one, nothing if a boundary holds it. Knows
     * the master dofs of every rank.
     */
    template <typename Add>
    void
    resolve_master_dof(const types::global_dof_index dof, const Add &add) const
    {
      const auto it = master_constraints.find(dof);
      if (it == master_constraints.end() || (!it->second.fixed && it->second.parents.empty()))
        add(dof, 1.);
      else
        for (const auto &[parent, weight] : it->second.parents)
          add(parent, weight);
    }

    /// The bodies (material ids) of the slave and of the master faces, on
    /// all ranks (after setup()).
    const std::set<types::material_id> &
    slave_bodies() const
    {
      return bodies[0];
    }

    const std::set<types::material_id> &
    master_bodies() const
    {
      return bodies[1];
    }

    /// The gap of a slave node that no master face covers: how far the
    /// search looked (a node further than this from the master is free).
    double
    search_distance() const
    {
      return reach;
    }

  private:
    static constexpr unsigned int n_face_vertices =
      GeometryInfo<dim - 1>::vertices_per_cell;

    /// A face: its vertices' dofs and reference positions, and which side
    /// of it is outside (the sign of its parametric normal, fixed on the
    /// reference configuration).
    struct Face
    {
      std::array<NodeDofs, n_face_vertices>   dofs;
      std::array<Point<dim>, n_face_vertices> reference;
      double                                  orientation = 1;
      /// Whether this rank owns the face's cell (and integrates it).
      bool                                    owned_cell = false;
    };

    /// The faces with @p id of the cells @p include picks.
    template <typename Include>
    std::vector<Face>
    collect_faces(const ElasticBody<dim> &body,
                  const types::boundary_id id,
                  const Include           &include) const;

    /// The current vertices of @p face for the displacement @p u_ghosted.
    MortarSegments::FaceVertices<dim>
    current_vertices(const Face &face, const Vector &u_ghosted) const;

    /// The slave nodes' normal_derivatives at the displacement @p u_ghosted
    /// (after their rows: a node with a master only).
    void
    take_normal_derivatives(const Vector &u_ghosted);

    /// The outward unit normal of a face with vertices @p x at its centre.
    static Tensor<1, dim>
    outward_normal(const MortarSegments::FaceVertices<dim> &x,
                   const double                             orientation);

    /// Every master face of every rank, in the current configuration.
    std::vector<std::pair<MortarSegments::FaceVertices<dim>, const Face *>>
    gather_master_faces(const Vector &u_ghosted, const MPI_Comm comm);

    /// Sums of a rigid master's rows at the slave dofs (written at every
    /// relevant dof, added over the ranks by compress): D_jj at the x dof,
    /// sum_l M_jl y_l and sum_l M_jl (y_l(t_end) - y_l(t_start)) at the
    /// component dofs.
    struct RigidRows
    {
      Vector weight, point, motion;
      /// With the tool's frames: sum_l M_jl n_l of the tool's vertex
      /// normals, and of the rows k of its faces' normal gradients.
      Vector                     normal;
      std::array<Vector, dim>    curvature;
    };

    /// The sums of @p rigid that this interface makes.
    std::vector<Vector *>
    rigid_sums(RigidRows &rigid) const;

    /// Resets the data of slave vertex @p dof to its normal and full
    /// weight (from the sums over the faces); returns its position for the
    /// displacement @p u_ghosted.
    Point<dim>
    start_node(const types::global_dof_index dof,
               const Vector                 &normal_sum,
               const Vector                 &lumped_sum,
               const Vector                 &u_ghosted);

    /// Whether the master covers enough of @p node's surface to give it a
    /// row; if not, the node is free this increment (weight 0, gap reach).
    bool
    covered(SlaveNode &node) const;

    /// An entry of M (slave row, master column) and its slide derivative.
    struct RowEntry
    {
      double         value = 0;
      Tensor<1, dim> slide;

      RowEntry &
      operator+=(const RowEntry &other)
      {
        value += other.value;
        slide += other.slide;
        return *this;
      }
    };
    using RowEntries =
      std::map<std::pair<types::global_dof_index, types::global_dof_index>, RowEntry>;

    /// A master vertex: its dofs, where the gaps are measured and where
    /// it is now.
    struct MasterVertex
    {
      NodeDofs   dofs;
      Point<dim> at_gaps;
      Point<dim> current;
    };

    /// The rows P_jl, gaps and gap slopes of a deformable master, from the
    /// entries of M this rank integrated (summed over the ranks here); the
    /// gaps measured at @p gap_displacement, the slopes at @p u_ghosted.
    void
    finish_rows(const Vector                                            &normal_sum,
                const Vector                                            &lumped_sum,
                const RowEntries                                        &M_entries,
                const std::map<types::global_dof_index, MasterVertex>   &master_vertex,
                const Vector                                            &gap_displacement,
                const Vector                                            &u_ghosted,
                const MPI_Comm                                           comm);

    /// An entry of M on its way to the rank that owns its row.
    struct MortarEntry
    {
      types::global_dof_index row, column;
      RowEntry                entry;

      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int)
      {
        archive &row &column &entry.value &entry.slide;
      }
    };

    /// The gaps and tool motions of a rigid master, from its row sums.
    void
    finish_rigid_rows(const Vector    &normal_sum,
                      const Vector    &lumped_sum,
                      const RigidRows &rigid,
                      const Vector    &u_ghosted);

    types::boundary_id    slave_id, master_id;
    const RigidTool<dim> *tool;
    /// Whether the scene is axisymmetric (setup()): the pair's integrals
    /// are then over the surfaces of revolution (weight 2 pi r).
    bool revolved = false;
    bool                  tool_frames = false;
    std::vector<Face>  slave_faces;
    /// The master faces of this rank's cells, and of all ranks (the dofs
    /// and orientations are gathered at setup, the positions at update).
    std::vector<Face>  local_master_faces;
    std::vector<Face>  all_master_faces;
    std::map<types::global_dof_index, SlaveNode> nodes;
    /// The dofs and reference position of each owned slave vertex.
    std::map<types::global_dof_index, std::pair<NodeDofs, Point<dim>>> slave_vertices;
    std::array<std::set<types::material_id>, 2>  bodies;
    /// How each master dof is held: fixed, or hanging from other dofs.
    struct MasterConstraint
    {
      bool                                                     fixed = false;
      std::vector<std::pair<types::global_dof_index, double>> parents;
    };
    std::map<types::global_dof_index, MasterConstraint> master_constraints;
    double reach = 0;
  };
} // namespace FrictionalContact
