// The mortar integrals of MortarSegments on flat non-matching interfaces,
// against D, M and weighted gaps computed by hand (exact fractions; see
// doc/algorithm.md, "Two bodies: mortar"): 2D, a slave line in 2 segments
// against a master in 3 (and the roles swapped); 3D, a slave square in 2 x 2
// quads against a master in 3 x 3, where everything is the tensor product of
// the 2D values; then the properties every interface must have: the dual
// basis is biorthogonal on a trapezoid, and on a distorted master the rows of
// M add up to D (constants) and reproduce the first moments (linear fields);
// and the derivatives of M as the slave slides along the master agree with
// its differences; a faceted master projected along its vertex normals
// covers the slave without gaps or overlaps.
#include <frictional_contact/model/mortar_segments.h>

#include <cmath>
#include <tuple>
#include <iostream>
#include <vector>

using namespace FrictionalContact;
using namespace FrictionalContact::MortarSegments;

namespace
{
  /// D (row sums) and M of slave faces against master faces, assembled.
  template <int dim>
  struct Assembled
  {
    std::vector<double>                              D;
    std::vector<std::vector<double>>                 M;
    std::vector<std::vector<Tensor<1, dim>>>         slide;
  };

  template <int dim>
  Assembled<dim>
  assemble(const std::vector<std::pair<FaceVertices<dim>, std::vector<unsigned int>>> &slave,
           const std::vector<std::pair<FaceVertices<dim>, std::vector<unsigned int>>> &master,
           const unsigned int n_slave,
           const unsigned int n_master,
           const Tensor<1, dim> &normal)
  {
    Assembled<dim> result;
    result.D.assign(n_slave, 0.);
    result.M.assign(n_slave, std::vector<double>(n_master, 0.));
    result.slide.assign(n_slave, std::vector<Tensor<1, dim>>(n_master));
    for (const auto &[s, s_nodes] : slave)
      for (const auto &[m, m_nodes] : master)
        {
          const FaceIntegrals<dim> integrals = face_integrals<dim>(s, normal, m);
          for (unsigned int a = 0; a < s_nodes.size(); ++a)
            for (unsigned int b = 0; b < m_nodes.size(); ++b)
              {
                result.M[s_nodes[a]][m_nodes[b]] += integrals.M(a, b);
                result.slide[s_nodes[a]][m_nodes[b]] += integrals.slide(a, b);
                result.D[s_nodes[a]] += integrals.M(a, b);
              }
        }
    return result;
  }

  /// The largest difference between the slide derivatives of the slave
  /// nodes @p slave_nodes against @p master and central differences of M
  /// as the whole slave slides by +-1e-6 along @p direction.
  template <int dim, typename MakeFaces, typename Faces>
  double
  slide_error(const std::vector<Point<dim>> &slave_nodes,
              const MakeFaces               &make_slave,
              const Faces                   &master,
              const unsigned int             n_master,
              const Tensor<1, dim>          &normal,
              const Tensor<1, dim>          &direction)
  {
    const double epsilon = 1e-6;
    const unsigned int n = slave_nodes.size();
    std::vector<Point<dim>> ahead = slave_nodes, behind = slave_nodes;
    for (unsigned int j = 0; j < n; ++j)
      {
        ahead[j] += epsilon * direction;
        behind[j] -= epsilon * direction;
      }
    const Assembled<dim> at     = assemble<dim>(make_slave(slave_nodes), master, n, n_master, normal);
    const Assembled<dim> plus   = assemble<dim>(make_slave(ahead), master, n, n_master, normal);
    const Assembled<dim> minus  = assemble<dim>(make_slave(behind), master, n, n_master, normal);
    double error = 0;
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int l = 0; l < n_master; ++l)
        error = std::max(error,
                         std::abs((plus.M[j][l] - minus.M[j][l]) / (2 * epsilon) -
                                  at.slide[j][l] * direction));
    return error;
  }

  /// Segments of a line at height y through the given x positions.
  std::vector<std::pair<FaceVertices<2>, std::vector<unsigned int>>>
  line(const std::vector<double> &x, const std::vector<double> &y)
  {
    std::vector<std::pair<FaceVertices<2>, std::vector<unsigned int>>> faces;
    for (unsigned int i = 0; i + 1 < x.size(); ++i)
      faces.push_back({{{Point<2>(x[i], y[i]), Point<2>(x[i + 1], y[i + 1])}}, {i, i + 1}});
    return faces;
  }

  /// n x n quads of the unit square at height z (deal.II vertex order),
  /// with the nodes numbered i + (n + 1) j; @p moved shifts some nodes.
  std::vector<std::pair<FaceVertices<3>, std::vector<unsigned int>>>
  grid(const unsigned int n, const double z, std::vector<Point<3>> &nodes)
  {
    if (nodes.empty())
      for (unsigned int j = 0; j <= n; ++j)
        for (unsigned int i = 0; i <= n; ++i)
          nodes.emplace_back(double(i) / n, double(j) / n, z);
    std::vector<std::pair<FaceVertices<3>, std::vector<unsigned int>>> faces;
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int i = 0; i < n; ++i)
        {
          const std::vector<unsigned int> ids = {i + (n + 1) * j, i + 1 + (n + 1) * j,
                                                 i + (n + 1) * (j + 1),
                                                 i + 1 + (n + 1) * (j + 1)};
          faces.push_back({{{nodes[ids[0]], nodes[ids[1]], nodes[ids[2]], nodes[ids[3]]}}, ids});
        }
    return faces;
  }

  void
  report(const std::string &what, const double error, const double bound)
  {
    std::cout << what << ": " << (error <= bound ? "yes" : "NO") << std::endl;
    if (error > bound)
      std::cout << "    (error " << error << ", allowed " << bound << ")" << std::endl;
  }
} // namespace



int
main()
{
  // 2D: slave x = 0, 1/2, 1 at y = 0 (normal +y), master x = 0, 1/3, 2/3, 1.
  const std::vector<double> xs = {0, 0.5, 1}, xm = {0, 1. / 3, 2. / 3, 1};
  const double              g0 = 0.01, slope = 0.02;
  std::vector<double>       ym;
  for (const double x : xm)
    ym.push_back(g0 + slope * x);
  Tensor<1, 2> up;
  up[1]                  = 1;
  const Assembled<2> two = assemble<2>(line(xs, {0, 0, 0}), line(xm, ym), 3, 4, up);
  // The projection along the slave normal does not see the tilt: M is that
  // of the flat master; the tilt shows in the gaps.
  const double D_exact[3]    = {1. / 4, 1. / 2, 1. / 4};
  const double M_exact[3][4] = {{2. / 9, 1. / 18, -1. / 36, 0},
                                {-1. / 18, 11. / 36, 11. / 36, -1. / 18},
                                {0, -1. / 36, 1. / 18, 2. / 9}};
  double       error_D = 0, error_M = 0, error_gap = 0, error_column = 0;
  for (unsigned int j = 0; j < 3; ++j)
    {
      error_D = std::max(error_D, std::abs(two.D[j] - D_exact[j]));
      double gap = 0;
      for (unsigned int l = 0; l < 4; ++l)
        {
          error_M = std::max(error_M, std::abs(two.M[j][l] - M_exact[j][l]));
          gap += two.M[j][l] / two.D[j] * (ym[l] - 0.);
        }
      // The nodal gap sum_l P_jl (y_l - x_j) . n is exact for a linear
      // master: g0 + slope x_j.
      error_gap = std::max(error_gap, std::abs(gap - (g0 + slope * xs[j])));
    }
  const double column_exact[4] = {1. / 6, 1. / 3, 1. / 3, 1. / 6};
  for (unsigned int l = 0; l < 4; ++l)
    {
      double column = 0;
      for (unsigned int j = 0; j < 3; ++j)
        column += two.M[j][l];
      error_column = std::max(error_column, std::abs(column - column_exact[l]));
    }
  report("2D: D = diag(1/4, 1/2, 1/4)", error_D, 1e-15);
  report("2D: M = [2/9 1/18 -1/36 0; -1/18 11/36 11/36 -1/18; 0 -1/36 1/18 2/9]",
         error_M, 1e-15);
  report("2D: column sums of M = the master's lumped lengths (1/6, 1/3, 1/3, 1/6)",
         error_column, 1e-15);
  report("2D: nodal gaps of a tilted master = g0 + a x_j", error_gap, 1e-15);

  // The roles swapped: slave in 3 segments, master in 2.
  const Assembled<2> swapped =
    assemble<2>(line(xm, {0, 0, 0, 0}), line(xs, {g0, g0, g0}), 4, 3, up);
  const double D_swapped[4]    = {1. / 6, 1. / 3, 1. / 3, 1. / 6};
  const double M_swapped[4][3] = {{1. / 6, 0, 0},
                                  {7. / 72, 1. / 4, -1. / 72},
                                  {-1. / 72, 1. / 4, 7. / 72},
                                  {0, 0, 1. / 6}};
  double error_swapped = 0;
  for (unsigned int j = 0; j < 4; ++j)
    {
      error_swapped = std::max(error_swapped, std::abs(swapped.D[j] - D_swapped[j]));
      for (unsigned int l = 0; l < 3; ++l)
        error_swapped = std::max(error_swapped, std::abs(swapped.M[j][l] - M_swapped[j][l]));
    }
  report("2D, slave and master swapped: D and M as by hand", error_swapped, 1e-15);

  // 3D: the tensor products of the 2D values.
  std::vector<Point<3>> slave_nodes, master_nodes;
  const auto            slave_faces  = grid(2, 0., slave_nodes);
  const auto            master_faces = grid(3, g0, master_nodes);
  Tensor<1, 3>          normal;
  normal[2] = 1;
  const Assembled<3> three = assemble<3>(slave_faces, master_faces, 9, 16, normal);
  double             error_3d = 0;
  for (unsigned int j = 0; j < 9; ++j)
    {
      const unsigned int ji = j % 3, jj = j / 3;
      error_3d = std::max(error_3d, std::abs(three.D[j] - D_exact[ji] * D_exact[jj]));
      for (unsigned int l = 0; l < 16; ++l)
        error_3d = std::max(error_3d,
                            std::abs(three.M[j][l] -
                                     M_exact[ji][l % 4] * M_exact[jj][l / 4]));
    }
  report("3D: D and M are the tensor products of the 2D ones "
         "(D = 1/16, 1/8, 1/4 at corners, edges, centre)",
         error_3d, 1e-14);

  // The dual basis of a trapezoid: int phi_a N_b = delta_ab int N_b.
  const FaceVertices<3> trapezoid = {{Point<3>(0, 0, 0), Point<3>(1, 0, 0),
                                      Point<3>(0, 1, 0), Point<3>(0.5, 1, 0)}};
  const Table<2, double> A = dual_coefficients<3>(trapezoid);
  double                 error_dual = 0;
  {
    // 4 x 4 Gauss on the face, with its Jacobian.
    const double g[4]  = {0.0694318442029737, 0.330009478207572, 0.669990521792428,
                         0.930568155797026};
    const double w[4]  = {0.173927422568727, 0.326072577431273, 0.326072577431273,
                         0.173927422568727};
    double       phi_N[4][4] = {}, lumped[4] = {};
    for (unsigned int i = 0; i < 4; ++i)
      for (unsigned int k = 0; k < 4; ++k)
        {
          const double x = g[i], y = g[k];
          // |x_xi x x_eta| of this trapezoid: 1 - y / 2.
          const double jacobian = 1 - y / 2;
          const auto   N        = shape_values<3>(Point<2>(x, y));
          for (unsigned int a = 0; a < 4; ++a)
            {
              lumped[a] += w[i] * w[k] * jacobian * N[a];
              double phi = 0;
              for (unsigned int b = 0; b < 4; ++b)
                phi += A(a, b) * N[b];
              for (unsigned int b = 0; b < 4; ++b)
                phi_N[a][b] += w[i] * w[k] * jacobian * phi * N[b];
            }
        }
    for (unsigned int a = 0; a < 4; ++a)
      for (unsigned int b = 0; b < 4; ++b)
        error_dual = std::max(error_dual,
                              std::abs(phi_N[a][b] - (a == b ? lumped[a] : 0.)));
  }
  report("3D: the dual basis of a trapezoid is biorthogonal", error_dual, 1e-14);

  // A distorted master (three interior nodes moved in the plane): constants
  // and linear fields are still transferred exactly.
  std::vector<Point<3>> moved;
  grid(3, g0, moved);
  moved[5]  = Point<3>(0.40, 0.30, g0);
  moved[6]  = Point<3>(0.62, 0.38, g0);
  moved[9]  = Point<3>(0.30, 0.70, g0);
  const auto distorted = grid(3, g0, moved);
  const Assembled<3> skewed = assemble<3>(slave_faces, distorted, 9, 16, normal);
  double error_rows = 0, error_moments = 0, error_weights = 0;
  for (unsigned int j = 0; j < 9; ++j)
    {
      double sum = 0;
      Tensor<1, 3> moment;
      for (unsigned int l = 0; l < 16; ++l)
        {
          sum += skewed.M[j][l];
          moment += skewed.M[j][l] * moved[l];
        }
      error_rows    = std::max(error_rows, std::abs(sum - skewed.D[j]));
      error_weights = std::max(error_weights,
                               std::abs(skewed.D[j] - D_exact[j % 3] * D_exact[j / 3]));
      for (unsigned int c = 0; c < 2; ++c)
        error_moments = std::max(error_moments,
                                 std::abs(moment[c] - skewed.D[j] * slave_nodes[j][c]));
    }
  report("3D, distorted master: D is unchanged", error_weights, 1e-14);
  report("3D, distorted master: the rows of M add up to D", error_rows, 1e-14);
  report("3D, distorted master: sum_l M_jl y_l = D_jj x_j (linear fields)",
         error_moments, 1e-14);

  // The slide derivatives (what the pairs' Newton tangent takes of the rows
  // moving along the master) against differences of M, for a slave inside
  // the master (so that the part covered does not change): the tilted 2D
  // master along x, the distorted 3D master along x and along a diagonal.
  {
    const std::vector<double> inner = {0.1, 0.45, 0.9};
    std::vector<Point<2>>     line_nodes;
    for (const double x : inner)
      line_nodes.emplace_back(x, 0.);
    const auto line_of = [](const std::vector<Point<2>> &nodes) {
      std::vector<double> x, y;
      for (const Point<2> &p : nodes)
        {
          x.push_back(p[0]);
          y.push_back(p[1]);
        }
      return line(x, y);
    };
    const double error_2d = slide_error<2>(
      line_nodes, line_of, line(xm, ym), 4, up, Tensor<1, 2>({1., 0.}));
    report("2D: the slide derivatives of M are its differences", error_2d, 1e-8);

    std::vector<Point<3>> square_nodes;
    for (unsigned int j = 0; j <= 2; ++j)
      for (unsigned int i = 0; i <= 2; ++i)
        square_nodes.emplace_back(0.1 + 0.37 * i, 0.12 + 0.4 * j, 0.);
    const auto square_of = [](const std::vector<Point<3>> &nodes) {
      std::vector<Point<3>> copy = nodes;
      return grid(2, 0., copy);
    };
    // On the distorted master the 7-point rule is not exact (the master's
    // shape functions are not polynomial on the overlap), and its error
    // moves with the overlap's vertices: differences and derivatives agree
    // to that error (the entries are about 0.3).
    double error_flat = 0, error_distorted = 0;
    for (const Tensor<1, 3> &direction :
         {Tensor<1, 3>({1., 0., 0.}), Tensor<1, 3>({0.6, 0.8, 0.})})
      {
        error_flat = std::max(
          error_flat, slide_error<3>(square_nodes, square_of, master_faces, 16, normal, direction));
        error_distorted = std::max(
          error_distorted, slide_error<3>(square_nodes, square_of, distorted, 16, normal, direction));
      }
    report("3D: the slide derivatives of M are its differences", error_flat, 1e-9);
    report("3D, distorted master: the same to the quadrature's error", error_distorted, 1e-5);
  }

  // The derivatives of a face's unit normal with respect to its vertices
  // (how the pairs' frames turn in the Newton tangent) against central
  // differences, on a tilted segment and a warped quad.
  {
    const auto normal_error = [](auto x) {
      constexpr int dim  = std::tuple_size<decltype(x)>::value == 2 ? 2 : 3;
      const auto    D    = unit_normal_derivatives<dim>(x);
      const double  step = 1e-6;
      double        error = 0;
      for (unsigned int v = 0; v < x.size(); ++v)
        for (unsigned int c = 0; c < dim; ++c)
          {
            auto plus = x, minus = x;
            plus[v][c] += step;
            minus[v][c] -= step;
            const Tensor<1, dim> difference =
              (unit_normal<dim>(plus) - unit_normal<dim>(minus)) / (2 * step);
            for (unsigned int i = 0; i < dim; ++i)
              error = std::max(error, std::abs(difference[i] - D[v][i][c]));
          }
      return error;
    };
    report("2D: the unit normal's derivatives are its differences",
           normal_error(FaceVertices<2>{{Point<2>(0.1, 0.2), Point<2>(0.7, 0.45)}}), 1e-8);
    report("3D: the same on a warped quad",
           normal_error(FaceVertices<3>{{Point<3>(0., 0., 0.), Point<3>(1.1, 0.1, 0.2),
                                         Point<3>(-0.1, 0.9, 0.1), Point<3>(1.2, 1.3, -0.3)}}),
           1e-8);
  }

  // A faceted convex master (a cylinder of radius 3 in facets of 10
  // degrees, as a rigid tool's surface) a little off a flat slave: with
  // the master's vertex normals the facets' images tile the slave face
  // (the rows of M add up to the full D); along each facet's own normal
  // they part at the shared vertices, which is why a tool's frames take
  // the vertex normals.
  {
    const double radius = 3, lift = 0.05;
    const auto   on_circle = [&](const double degrees) {
      const double angle = degrees * M_PI / 180;
      return Tensor<1, 2>({std::cos(angle), std::sin(angle)});
    };
    const Point<2>    centre(0., radius + lift);
    const FaceVertices<2> slave_line{{Point<2>(-0.5, 0.), Point<2>(0.5, 0.)}};
    double            rows_2d[2] = {0, 0}, rows_own_normals[2] = {0, 0};
    for (double degrees = 250; degrees < 290; degrees += 10)
      {
        const MasterNormals<2> normals{{on_circle(degrees), on_circle(degrees + 10)}};
        const FaceVertices<2>  facet{{centre + radius * normals[0], centre + radius * normals[1]}};
        const FaceIntegrals<2> along_vertices =
          face_integrals<2>(slave_line, Tensor<1, 2>({0., 1.}), facet, &normals);
        const FaceIntegrals<2> along_own =
          face_integrals<2>(slave_line, unit_normal<2>(facet), facet);
        for (unsigned int a = 0; a < 2; ++a)
          for (unsigned int b = 0; b < 2; ++b)
            {
              rows_2d[a] += along_vertices.M(a, b);
              rows_own_normals[a] += along_own.M(a, b);
            }
      }
    report("2D, faceted master along its vertex normals: the rows of M add up to D",
           std::max(std::abs(rows_2d[0] - 0.5), std::abs(rows_2d[1] - 0.5)), 1e-14);
    const double parted =
      std::max(std::abs(rows_own_normals[0] - 0.5), std::abs(rows_own_normals[1] - 0.5));
    std::cout << "2D, the same along each facet's own normal: the images part: "
              << (parted > 1e-5 ? "yes" : "no") << std::endl;

    // The same in 3D: facets along y from -1 to 1, the slave the unit square.
    const Point<3>    axis_point(0., 0., radius + lift);
    FaceVertices<3>   square;
    for (unsigned int v = 0; v < 4; ++v)
      square[v] = Point<3>(v % 2 == 0 ? -0.5 : 0.5, v < 2 ? -0.5 : 0.5, 0.);
    std::array<double, 4> rows_3d{};
    for (double degrees = 250; degrees < 290; degrees += 10)
      {
        MasterNormals<3> normals;
        FaceVertices<3>  facet;
        for (unsigned int v = 0; v < 4; ++v)
          {
            const Tensor<1, 2> radial = on_circle(degrees + (v % 2) * 10);
            normals[v] = Tensor<1, 3>({radial[0], 0., radial[1]});
            facet[v]   = axis_point + radius * normals[v] +
                       Tensor<1, 3>({0., v < 2 ? -1. : 1., 0.});
          }
        const FaceIntegrals<3> integrals =
          face_integrals<3>(square, Tensor<1, 3>({0., 0., 1.}), facet, &normals);
        for (unsigned int a = 0; a < 4; ++a)
          for (unsigned int b = 0; b < 4; ++b)
            rows_3d[a] += integrals.M(a, b);
      }
    double error_3d = 0;
    for (const double row : rows_3d)
      error_3d = std::max(error_3d, std::abs(row - 0.25));
    report("3D, faceted master along its vertex normals: the rows of M add up to D",
           error_3d, 1e-14);
  }
  return 0;
}
