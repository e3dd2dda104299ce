#pragma once

#include <deal.II/base/geometry_info.h>
#include <deal.II/base/point.h>
#include <deal.II/base/table.h>
#include <deal.II/base/tensor.h>

#include <array>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * The mortar integrals of one slave face against one master face, the
   * geometric kernel of MortarInterface (no mesh, no MPI; unit-tested on
   * flat non-matching interfaces whose integrals are known by hand). A face
   * of a Q1 cell is a 2-node segment in 2D and a bilinear quad in 3D, its
   * vertices in deal.II's order. The slave side carries the dual
   * (biorthogonal) basis phi_a = sum_b A_ab N_b with A = D_e M_e^-1 of the
   * face (Wohlmuth), so that int phi_a N_b = delta_ab int N_b.
   *
   * The overlap is found on the slave face's plane (its line in 2D): the
   * master face is projected onto it along the slave face's normal, the two
   * polygons are clipped (Sutherland-Hodgman; segments overlap in 2D), the
   * overlap is cut into triangles from its centroid and integrated with a
   * 7-point degree-5 rule (2 Gauss points in 2D), each point mapped back to
   * both faces. On flat faces with affine geometry the result is exact.
   */
  namespace MortarSegments
  {
    template <int dim>
    using FaceVertices =
      std::array<Point<dim>, GeometryInfo<dim - 1>::vertices_per_cell>;

    /// The mortar integrals of a slave face against a master face.
    template <int dim>
    struct FaceIntegrals
    {
      /// M(a, b) = int phi_a N_b, for slave vertex a and master vertex b.
      Table<2, double> M;
      /// int phi_a grad N_b, the gradient of the master's shape function
      /// across the projection direction: where the slave face slides by
      /// delta along the master, M(a, b) changes by slide(a, b) . delta.
      Table<2, Tensor<1, dim>> slide;
    };

    /// Unit normals at the vertices of a master face.
    template <int dim>
    using MasterNormals =
      std::array<Tensor<1, dim>, GeometryInfo<dim - 1>::vertices_per_cell>;

    /**
     * The integrals over the overlap of @p slave and @p master;
     * @p slave_normal is the slave face's outward unit normal (at its
     * centre), along which the master is projected. With
     * @p master_normals, each master vertex is projected along its own
     * normal instead (the overlap is then found on the plane normal to
     * @p slave_normal, and the master's coordinates are those of the
     * projected face): the faces of a faceted master with shared vertex
     * normals then cover the slave face without gaps or overlaps. Zero if
     * they do not overlap or do not face each other. The row sums of M
     * are the weights D_aa = int phi_a over the covered part. With
     * @p revolved (2D: an axisymmetric scene, x = r), the integrals are
     * over the surfaces of revolution, with the weight 2 pi r, and the
     * dual basis is biorthogonal in that measure.
     */
    template <int dim>
    FaceIntegrals<dim>
    face_integrals(const FaceVertices<dim>  &slave,
                   const Tensor<1, dim>     &slave_normal,
                   const FaceVertices<dim>  &master,
                   const MasterNormals<dim> *master_normals = nullptr,
                   const bool                revolved       = false);

    /// The dual basis coefficients A = D_e M_e^-1 of the slave face (with
    /// the weight r where @p revolved; exposed for the tests:
    /// biorthogonality on any quad).
    template <int dim>
    Table<2, double>
    dual_coefficients(const FaceVertices<dim> &slave, const bool revolved = false);

    /// The unit normal of a face at its centre, (x_1 - x_0) turned
    /// clockwise in 2D, a x b for the mean edge vectors a (along the first
    /// face coordinate) and b in 3D: the side it points to follows the
    /// vertex order.
    template <int dim>
    Tensor<1, dim>
    unit_normal(const FaceVertices<dim> &x);

    /// The derivatives of unit_normal() with respect to each vertex:
    /// dn = sum_v D_v dx_v.
    template <int dim>
    std::array<Tensor<2, dim>, GeometryInfo<dim - 1>::vertices_per_cell>
    unit_normal_derivatives(const FaceVertices<dim> &x);

    /**
     * The gradient at the face's centre of the normal field interpolated
     * (Q1) from the unit @p normals at its vertices, along the face: G with
     * dn = G dx for a move dx of the point where it is taken (the surface's
     * curvature for the normals of a smooth surface).
     */
    template <int dim>
    Tensor<2, dim>
    normal_gradient(const FaceVertices<dim>                                             &x,
                    const std::array<Tensor<1, dim>, GeometryInfo<dim - 1>::vertices_per_cell> &normals);

    /// The Q1 shape values of a face at the face coordinates @p xi.
    template <int dim>
    std::array<double, GeometryInfo<dim - 1>::vertices_per_cell>
    shape_values(const Point<dim - 1> &xi);
  } // namespace MortarSegments
} // namespace FrictionalContact
