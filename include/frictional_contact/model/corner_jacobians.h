#pragma once

#include <deal.II/base/geometry_info.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <algorithm>
#include <array>
#include <limits>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * The smallest det F at the vertices of a Q1 cell displaced by Q1
   * displacements: at vertex v the edges to its neighbours along the
   * reference axes are the columns of dx/dxi there (exactly, the map being
   * multilinear), and det F = det(dx/dxi) / det(dX/dxi). The Gauss points
   * alone miss a cell folded at a corner: the 2D ironing on cells of
   * 0.0625 converged, without friction, to states where two cells under
   * the die had a corner at det F = -0.21 while det F > 0 at every Gauss
   * point, and the next increments then stalled. In 2D a bilinear cell
   * whose corners are positive is positive everywhere; in 3D the corners
   * are necessary, not sufficient.
   *
   * @p vertices are the cell's reference vertices, @p displacement the
   * displacement of each vertex, both in deal.II's vertex numbering.
   */
  template <int dim>
  double
  smallest_corner_jacobian(
    const std::array<Point<dim>, GeometryInfo<dim>::vertices_per_cell>     &vertices,
    const std::array<Tensor<1, dim>, GeometryInfo<dim>::vertices_per_cell> &displacement)
  {
    double smallest = std::numeric_limits<double>::max();
    for (unsigned int v = 0; v < GeometryInfo<dim>::vertices_per_cell; ++v)
      {
        Tensor<2, dim> reference, deformed;
        for (unsigned int d = 0; d < dim; ++d)
          {
            // The neighbour along axis d, and the edge's sign: vertex
            // v's bit d says whether it is at xi_d = 0 or 1.
            const unsigned int w    = v ^ (1u << d);
            const double       sign = (v >> d) & 1u ? -1. : 1.;
            for (unsigned int c = 0; c < dim; ++c)
              {
                reference[c][d] = sign * (vertices[w][c] - vertices[v][c]);
                deformed[c][d]  = reference[c][d] +
                                 sign * (displacement[w][c] - displacement[v][c]);
              }
          }
        smallest = std::min(smallest, determinant(deformed) / determinant(reference));
      }
    return smallest;
  }
} // namespace FrictionalContact
