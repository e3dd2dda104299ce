#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/numerics/rtree.h>

#include <frictional_contact/base/gather_doubles.h>
#include <frictional_contact/model/mortar_interface.h>

#include <boost/geometry/index/rtree.hpp>

#include <algorithm>

namespace FrictionalContact
{
  namespace
  {
    /// The integral of each vertex's Q1 function over the face @p x (of
    /// the surface of revolution it sweeps where @p revolved: 2D only).
    template <int dim>
    std::array<double, GeometryInfo<dim - 1>::vertices_per_cell>
    lumped_weights(const MortarSegments::FaceVertices<dim> &x, const bool revolved)
    {
      std::array<double, GeometryInfo<dim - 1>::vertices_per_cell> weights{};
      if constexpr (dim == 2)
        {
          // int_0^1 (1 - s) (r_0 (1 - s) + r_1 s) ds = r_0 / 3 + r_1 / 6.
          const double length = x[0].distance(x[1]);
          weights[0]          = length / 2;
          weights[1]          = length / 2;
          if (revolved)
            {
              weights[0] = 2 * numbers::PI * length * (x[0][0] / 3 + x[1][0] / 6);
              weights[1] = 2 * numbers::PI * length * (x[1][0] / 3 + x[0][0] / 6);
            }
        }
      else
        {
          const QGauss<2> gauss(2);
          for (unsigned int q = 0; q < gauss.size(); ++q)
            {
              const double s = gauss.point(q)[0], t = gauss.point(q)[1];
              const Tensor<1, 3> xs = (1 - t) * (x[1] - x[0]) + t * (x[3] - x[2]);
              const Tensor<1, 3> xt = (1 - s) * (x[2] - x[0]) + s * (x[3] - x[1]);
              const auto N = MortarSegments::shape_values<3>(gauss.point(q));
              const double dx = gauss.weight(q) * cross_product_3d(xs, xt).norm();
              for (unsigned int a = 0; a < 4; ++a)
                weights[a] += N[a] * dx;
            }
        }
      return weights;
    }
  } // namespace



  template <int dim>
  MortarInterface<dim>::MortarInterface(const types::boundary_id slave,
                                        const types::boundary_id master,
                                        const RigidTool<dim>    *tool)
    : slave_id(slave)
    , master_id(master)
    , tool(tool)
  {}



  template <int dim>
  Tensor<1, dim>
  MortarInterface<dim>::outward_normal(const MortarSegments::FaceVertices<dim> &x,
                                       const double orientation)
  {
    return orientation * MortarSegments::unit_normal<dim>(x);
  }



  template <int dim>
  template <typename Include>
  std::vector<typename MortarInterface<dim>::Face>
  MortarInterface<dim>::collect_faces(const ElasticBody<dim>   &body,
                                      const types::boundary_id id,
                                      const Include           &include) const
  {
    std::vector<Face> faces;
    for (const auto &cell : body.get_dof_handler().active_cell_iterators())
      if (!cell->is_artificial() && include(cell))
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && face->boundary_id() == id)
            {
              Face                              f;
              MortarSegments::FaceVertices<dim> x;
              for (unsigned int v = 0; v < n_face_vertices; ++v)
                {
                  for (unsigned int c = 0; c < dim; ++c)
                    f.dofs[v][c] = face->vertex_dof_index(v, c);
                  f.reference[v] = x[v] = face->vertex(v);
                }
              f.owned_cell = cell->is_locally_owned();
              // Outside is away from the cell's centre.
              f.orientation =
                outward_normal(x, 1.) * (face->center() - cell->center()) > 0 ? 1. : -1.;
              faces.push_back(f);
            }
    return faces;
  }



  template <int dim>
  void
  MortarInterface<dim>::setup(const ElasticBody<dim> &body)
  {
    const IndexSet &owned = body.locally_owned_dofs();
    const MPI_Comm  comm  = body.get_mpi_communicator();
    revolved              = body.get_materials().axisymmetric();
    // The slave faces of every cell this rank sees (to find the slave
    // vertices it owns); only those of its own cells are integrated.
    slave_faces = collect_faces(body, slave_id, [](const auto &) { return true; });
    // A rigid tool's faces are not the mesh's.
    local_master_faces =
      collect_faces(body, master_id, [this](const auto &cell) {
        return tool == nullptr && cell->is_locally_owned();
      });
    for (unsigned int side = 0; side < 2; ++side)
      {
        std::set<types::material_id> found;
        for (const auto &cell : body.get_dof_handler().active_cell_iterators())
          if (cell->is_locally_owned())
            for (const auto &face : cell->face_iterators())
              if (face->at_boundary() &&
                  face->boundary_id() == (side == 0 ? slave_id : master_id))
                found.insert(cell->material_id());
        bodies[side] = Utilities::MPI::compute_set_union(found, comm);
      }

    // Every rank gets every master face's dofs and orientation.
    std::vector<double> packed;
    for (const Face &face : local_master_faces)
      {
        for (const NodeDofs &dofs : face.dofs)
          for (const auto dof : dofs)
            packed.push_back(static_cast<double>(dof));
        packed.push_back(face.orientation);
      }
    all_master_faces.clear();
    const unsigned int stride = n_face_vertices * dim + 1;
    for (const std::vector<double> &part : gather_doubles(comm, packed))
      for (std::size_t k = 0; k + stride <= part.size(); k += stride)
        {
          Face face;
          for (unsigned int v = 0; v < n_face_vertices; ++v)
            for (unsigned int c = 0; c < dim; ++c)
              face.dofs[v][c] =
                static_cast<types::global_dof_index>(part[k + v * dim + c]);
          face.orientation = part[k + stride - 1];
          all_master_faces.push_back(face);
        }

    // Every rank gets the constraints of every master dof: a fixed or
    // hanging one may belong to a part of the mesh this rank cannot see.
    // Packed as: dof, then -1 (fixed), 0 (free) or the number of the dofs
    // it hangs from, followed by (dof, weight) pairs.
    const AffineConstraints<double> &constraints = body.get_constraints();
    std::vector<double>              constraint_data;
    for (const Face &face : local_master_faces)
      for (const NodeDofs &dofs : face.dofs)
        for (const auto dof : dofs)
          {
            constraint_data.push_back(static_cast<double>(dof));
            if (!constraints.is_constrained(dof))
              constraint_data.push_back(0);
            else
              {
                const auto *entries = constraints.get_constraint_entries(dof);
                if (entries->empty())
                  constraint_data.push_back(-1);
                else
                  {
                    constraint_data.push_back(static_cast<double>(entries->size()));
                    for (const auto &[parent, weight] : *entries)
                      {
                        constraint_data.push_back(static_cast<double>(parent));
                        constraint_data.push_back(weight);
                      }
                  }
              }
          }
    master_constraints.clear();
    for (const std::vector<double> &part : gather_doubles(comm, constraint_data))
      for (std::size_t k = 0; k < part.size();)
        {
          const auto dof  = static_cast<types::global_dof_index>(part[k]);
          const int  kind = static_cast<int>(part[k + 1]);
          k += 2;
          auto &entry = master_constraints[dof];
          entry.fixed = kind < 0;
          entry.parents.clear();
          for (int e = 0; e < kind; ++e, k += 2)
            entry.parents.emplace_back(static_cast<types::global_dof_index>(part[k]),
                                       part[k + 1]);
        }

    nodes.clear();
    slave_vertices.clear();
    double largest = 0;
    for (const Face &face : slave_faces)
      {
        for (unsigned int v = 0; v < n_face_vertices; ++v)
          if (owned.is_element(face.dofs[v][0]))
            {
              nodes[face.dofs[v][0]];
              slave_vertices[face.dofs[v][0]] = {face.dofs[v], face.reference[v]};
            }
        for (unsigned int v = 0; v < n_face_vertices; ++v)
          for (unsigned int w = 0; w < v; ++w)
            largest = std::max(largest, face.reference[v].distance(face.reference[w]));
      }
    reach = 2 * Utilities::MPI::max(largest, comm);
  }



  template <int dim>
  MortarSegments::FaceVertices<dim>
  MortarInterface<dim>::current_vertices(const Face   &face,
                                         const Vector &u_ghosted) const
  {
    MortarSegments::FaceVertices<dim> x;
    for (unsigned int v = 0; v < n_face_vertices; ++v)
      {
        x[v] = face.reference[v];
        for (unsigned int c = 0; c < dim; ++c)
          x[v][c] += u_ghosted[face.dofs[v][c]];
      }
    return x;
  }



  template <int dim>
  std::vector<std::pair<MortarSegments::FaceVertices<dim>,
                        const typename MortarInterface<dim>::Face *>>
  MortarInterface<dim>::gather_master_faces(const Vector  &u_ghosted,
                                            const MPI_Comm comm)
  {
    std::vector<double> packed;
    for (const Face &face : local_master_faces)
      for (const Point<dim> &x : current_vertices(face, u_ghosted))
        for (unsigned int c = 0; c < dim; ++c)
          packed.push_back(x[c]);
    std::vector<std::pair<MortarSegments::FaceVertices<dim>, const Face *>> faces;
    const unsigned int stride = n_face_vertices * dim;
    unsigned int       index  = 0;
    for (const std::vector<double> &part : gather_doubles(comm, packed))
      for (std::size_t k = 0; k + stride <= part.size(); k += stride, ++index)
        {
          MortarSegments::FaceVertices<dim> x;
          for (unsigned int v = 0; v < n_face_vertices; ++v)
            for (unsigned int c = 0; c < dim; ++c)
              x[v][c] = part[k + v * dim + c];
          faces.emplace_back(x, &all_master_faces[index]);
        }
    return faces;
  }



  template <int dim>
  void
  MortarInterface<dim>::update(const ElasticBody<dim> &body,
                               const Vector           &u_ghosted,
                               const double            t_start,
                               const double            t_end,
                               const Vector           *gaps_at)
  {
    const MPI_Comm  comm     = body.get_mpi_communicator();
    const IndexSet &owned    = body.locally_owned_dofs();
    const IndexSet &relevant = body.locally_relevant_dofs();
    // The master faces in the current configuration: the body's of every
    // rank, or the tool's where it stands at t_end (and where it stood).
    std::vector<std::pair<MortarSegments::FaceVertices<dim>, const Face *>> masters;
    std::vector<MortarSegments::FaceVertices<dim>> tool_at_start;
    if (tool != nullptr)
      {
        for (const auto &y : tool->faces_at(t_end))
          masters.emplace_back(y, nullptr);
        tool_at_start = tool->faces_at(t_start);
      }
    else
      masters = gather_master_faces(u_ghosted, comm);
    // The gaps are measured at u_ghosted, or with this geometry at gaps_at.
    const Vector &gap_displacement = gaps_at != nullptr ? *gaps_at : u_ghosted;
    const auto    masters_at_gaps  = tool == nullptr && gaps_at != nullptr ?
                                       gather_master_faces(*gaps_at, comm) :
                                       masters;

    std::vector<std::pair<BoundingBox<dim>, unsigned int>> boxes;
    std::map<types::global_dof_index, MasterVertex> master_vertex;
    for (unsigned int m = 0; m < masters.size(); ++m)
      {
        const auto &[y, face] = masters[m];
        boxes.emplace_back(BoundingBox<dim>(std::vector<Point<dim>>(y.begin(), y.end())),
                           m);
        if (face != nullptr)
          for (unsigned int b = 0; b < n_face_vertices; ++b)
            master_vertex[face->dofs[b][0]] = {face->dofs[b],
                                               masters_at_gaps[m].first[b],
                                               y[b]};
      }
    const auto tree = pack_rtree(boxes);

    // Each face of this rank's cells adds, once, to the rows of its
    // vertices: the face normal at each component dof, the lumped weight and
    // the row of M at the x dof (for a tool, its sums). A hanging vertex has
    // no multiplier of its own: its part goes to the vertices it hangs from,
    // with the constraint's weights (as its force and area do in
    // ContactOperator).
    const AffineConstraints<double> &hanging = body.get_hanging_node_constraints();
    const auto to_parents = [&](const types::global_dof_index dof, const auto &add) {
      if (!hanging.is_constrained(dof))
        add(dof, 1.);
      else
        for (const auto &[parent, weight] : *hanging.get_constraint_entries(dof))
          add(parent, weight);
    };
    // Written also at the vertices other ranks own: added there at compress.
    Vector normal_sum, lumped_sum;
    normal_sum.reinit(owned, relevant, comm, true);
    lumped_sum.reinit(owned, relevant, comm, true);
    RigidRows rigid;
    if (tool != nullptr)
      for (Vector *v : rigid_sums(rigid))
        v->reinit(owned, relevant, comm, true);
    // With the tool's frames: its vertex normals and each face's gradient
    // of the normal field they interpolate.
    std::vector<std::array<Tensor<1, dim>, n_face_vertices>> tool_normals;
    std::vector<Tensor<2, dim>>                              tool_gradients;
    if (tool_frames)
      {
        tool_normals = tool->vertex_normals_at(t_end);
        for (unsigned int m = 0; m < masters.size(); ++m)
          tool_gradients.push_back(
            MortarSegments::normal_gradient<dim>(masters[m].first, tool_normals[m]));
      }
    RowEntries M_entries;
    for (const Face &face : slave_faces)
      if (face.owned_cell)
        {
          const MortarSegments::FaceVertices<dim> x = current_vertices(face, u_ghosted);
          const Tensor<1, dim> normal = outward_normal(x, face.orientation);
          const auto           lumped = lumped_weights<dim>(x, revolved);
          for (unsigned int a = 0; a < n_face_vertices; ++a)
            {
              for (unsigned int c = 0; c < dim; ++c)
                to_parents(face.dofs[a][c], [&](const auto dof, const double w) {
                  normal_sum[dof] += w * normal[c];
                });
              to_parents(face.dofs[a][0], [&](const auto dof, const double w) {
                lumped_sum[dof] += w * lumped[a];
              });
            }

          BoundingBox<dim> search(std::vector<Point<dim>>(x.begin(), x.end()));
          search.extend(reach);
          std::vector<std::pair<BoundingBox<dim>, unsigned int>> near;
          tree.query(boost::geometry::index::intersects(search), std::back_inserter(near));
          for (const auto &[box, m] : near)
            {
              const auto &[y, master] = masters[m];
              const double orientation = master != nullptr ? master->orientation : 1.;
              const Tensor<1, dim> master_normal = outward_normal(y, orientation);
              const double         facing        = -(master_normal * normal);
              if (facing <= 0)
                continue; // not facing the slave
              // Projected along the slave's normal, or with the tool's
              // frames along the tool's vertex normals, as a distance to it
              // is measured (along each tool face's own normal, the images
              // of two faces overlap or part at their shared edge, and a
              // slave node there turned its frame twice as fast as its
              // motion, or not at all); then a tool face's part fades from
              // whole at 30 degrees from facing the slave face to none at 60
              // (further, its projection would land far from it; a sudden
              // cut made the geometry jump).
              const double fade =
                tool_frames ? std::clamp((facing - 0.5) / (std::sqrt(0.75) - 0.5), 0., 1.) : 1.;
              if (fade == 0)
                continue;
              MortarSegments::FaceIntegrals<dim> integrals = MortarSegments::face_integrals<dim>(
                x, normal, y, tool_frames ? &tool_normals[m] : nullptr, revolved);
              Table<2, double> &M = integrals.M;
              if (fade < 1)
                for (unsigned int a = 0; a < n_face_vertices; ++a)
                  for (unsigned int b = 0; b < n_face_vertices; ++b)
                    M(a, b) *= fade;
              for (unsigned int a = 0; a < n_face_vertices; ++a)
                for (unsigned int b = 0; b < n_face_vertices; ++b)
                  if (M(a, b) == 0)
                    continue;
                  else if (master != nullptr)
                    to_parents(face.dofs[a][0], [&](const auto dof, const double w) {
                      M_entries[{dof, master->dofs[b][0]}] +=
                        RowEntry{w * M(a, b), w * integrals.slide(a, b)};
                    });
                  else
                    {
                      const Tensor<1, dim> motion = y[b] - tool_at_start[m][b];
                      to_parents(face.dofs[a][0], [&](const auto dof, const double w) {
                        rigid.weight[dof] += w * M(a, b);
                      });
                      for (unsigned int c = 0; c < dim; ++c)
                        to_parents(face.dofs[a][c], [&](const auto dof, const double w) {
                          rigid.point[dof] += w * M(a, b) * y[b][c];
                          rigid.motion[dof] += w * M(a, b) * motion[c];
                          if (tool_frames)
                            {
                              rigid.normal[dof] += w * M(a, b) * tool_normals[m][b][c];
                              for (unsigned int k = 0; k < dim; ++k)
                                rigid.curvature[k][dof] +=
                                  w * M(a, b) * tool_gradients[m][k][c];
                            }
                        });
                    }
            }
        }
    normal_sum.compress(VectorOperation::add);
    lumped_sum.compress(VectorOperation::add);
    if (tool != nullptr)
      {
        for (Vector *v : rigid_sums(rigid))
          v->compress(VectorOperation::add);
        finish_rigid_rows(normal_sum, lumped_sum, rigid, gap_displacement);
      }
    else
      {
        finish_rows(normal_sum, lumped_sum, M_entries, master_vertex, gap_displacement,
                    u_ghosted, comm);
        if (gaps_at != nullptr)
          take_normal_derivatives(u_ghosted);
      }
  }



  template <int dim>
  std::vector<TrilinosWrappers::MPI::Vector *>
  MortarInterface<dim>::rigid_sums(RigidRows &rigid) const
  {
    std::vector<Vector *> sums = {&rigid.weight, &rigid.point, &rigid.motion};
    if (tool_frames)
      {
        sums.push_back(&rigid.normal);
        for (Vector &row : rigid.curvature)
          sums.push_back(&row);
      }
    return sums;
  }



  template <int dim>
  const typename MortarInterface<dim>::SlaveNode *
  MortarInterface<dim>::node(const types::global_dof_index dof) const
  {
    const auto it = nodes.find(dof);
    return it == nodes.end() ? nullptr : &it->second;
  }

  template class MortarInterface<2>;
  template class MortarInterface<3>;
} // namespace FrictionalContact
