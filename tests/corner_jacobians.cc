// smallest_corner_jacobian() on the unit square and cube with their last
// vertex moved towards the first (by 0.6 and 0.4 along each axis), past
// the line or plane of its neighbours: det F
// is negative at that corner while the 2 x 2 (x 2) Gauss points all have
// det F > 0 (which is why the corners are checked too); an affine map
// gives its own det F at every corner, and a rotated cell 1.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>

#include <frictional_contact/model/corner_jacobians.h>

#include <iomanip>
#include <iostream>

using namespace FrictionalContact;

namespace
{
  template <int dim>
  using Corners = std::array<Tensor<1, dim>, GeometryInfo<dim>::vertices_per_cell>;

  /// The smallest det F at the Gauss points of the Q1 map of the unit
  /// cell by @p displacement.
  template <int dim>
  double
  smallest_at_gauss_points(const Corners<dim> &displacement)
  {
    const FE_Q<dim>   fe(1);
    const QGauss<dim> gauss(2);
    double            smallest = 1e300;
    for (unsigned int q = 0; q < gauss.size(); ++q)
      {
        Tensor<2, dim> F = unit_symmetric_tensor<dim>();
        for (unsigned int a = 0; a < fe.n_dofs_per_cell(); ++a)
          F += outer_product(displacement[a], fe.shape_grad(a, gauss.point(q)));
        smallest = std::min(smallest, determinant(F));
      }
    return smallest;
  }

  template <int dim>
  void
  check(const std::string &title, const Corners<dim> &displacement)
  {
    std::array<Point<dim>, GeometryInfo<dim>::vertices_per_cell> vertices;
    for (unsigned int v = 0; v < vertices.size(); ++v)
      vertices[v] = GeometryInfo<dim>::unit_cell_vertex(v);
    std::cout << dim << "D " << title << ": corners " << std::setprecision(6)
              << smallest_corner_jacobian<dim>(vertices, displacement)
              << ", Gauss points " << smallest_at_gauss_points<dim>(displacement)
              << std::endl;
  }

  template <int dim>
  void
  check_all()
  {
    const unsigned int last = GeometryInfo<dim>::vertices_per_cell - 1;
    const double       move = dim == 2 ? 0.6 : 0.4;
    Corners<dim>       folded, affine, rotated;
    for (unsigned int c = 0; c < dim; ++c)
      folded[last][c] = -move;
    check<dim>("last vertex moved by -" + std::to_string(move).substr(0, 3) +
                 " along each axis",
               folded);
    // x -> (0.5 x_0, x_1, ...) + shift: det F = 0.5 everywhere.
    for (unsigned int v = 0; v <= last; ++v)
      {
        const Point<dim> X = GeometryInfo<dim>::unit_cell_vertex(v);
        affine[v][0]       = -0.5 * X[0] + 0.3;
        // A quarter turn about the last axis, x_0 -> x_1 -> -x_0.
        rotated[v][0] = -X[1] - X[0];
        rotated[v][1] = X[0] - X[1];
      }
    check<dim>("halved along the first axis", affine);
    check<dim>("turned by a quarter", rotated);
  }
} // namespace

int
main()
{
  check_all<2>();
  check_all<3>();
}
