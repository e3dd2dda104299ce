#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/lac/full_matrix.h>

#include <frictional_contact/model/mortar_segments.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace FrictionalContact
{
  namespace MortarSegments
  {
    namespace
    {
      using Point2 = std::array<double, 2>;

      double
      cross_2d(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
      {
        return a[0] * b[1] - a[1] * b[0];
      }

      /// The point of the face at @p xi, and its two (one) tangents.
      template <int dim>
      Point<dim>
      face_point(const FaceVertices<dim> &v, const Point<dim - 1> &xi)
      {
        const auto N = shape_values<dim>(xi);
        Point<dim> x;
        for (unsigned int a = 0; a < N.size(); ++a)
          x += N[a] * v[a];
        return x;
      }

      /// d x / d xi_k of the bilinear face at @p xi.
      Tensor<1, 3>
      face_tangent(const FaceVertices<3> &v, const Point<2> &xi, const unsigned int k)
      {
        const double x = xi[0], y = xi[1];
        const double dN[2][4] = {{-(1 - y), 1 - y, -y, y},
                                 {-(1 - x), -x, 1 - x, x}};
        Tensor<1, 3> t;
        for (unsigned int a = 0; a < 4; ++a)
          t += dN[k][a] * v[a];
        return t;
      }

      /// The face coordinates of the point of @p v that @p X projects to
      /// along @p n (Newton on x(xi) + alpha n = X), clamped to [0, 1]^2;
      /// with @p gradient also d xi_k / d X (zero where xi_k is clamped).
      Point<2>
      inverse_map(const FaceVertices<3>        &v,
                  const Point<3>               &X,
                  const Tensor<1, 3>           &n,
                  std::array<Tensor<1, 3>, 2> *gradient = nullptr)
      {
        Point<2> xi(0.5, 0.5);
        double   alpha = 0;
        for (unsigned int iteration = 0; iteration < 30; ++iteration)
          {
            const Tensor<1, 3> residual =
              face_point<3>(v, xi) + alpha * n - X;
            // The Jacobian's columns: the face's tangents and n.
            Tensor<2, 3>       J;
            const Tensor<1, 3> t0 = face_tangent(v, xi, 0), t1 = face_tangent(v, xi, 1);
            for (unsigned int c = 0; c < 3; ++c)
              {
                J[c][0] = t0[c];
                J[c][1] = t1[c];
                J[c][2] = n[c];
              }
            const Tensor<1, 3> step = invert(J) * residual;
            xi[0] -= step[0];
            xi[1] -= step[1];
            alpha -= step[2];
            if (std::abs(step[0]) + std::abs(step[1]) < 1e-15)
              break;
          }
        if (gradient != nullptr)
          {
            // The rows of the inverse of the Jacobian (t0, t1, n).
            const Tensor<1, 3> t0 = face_tangent(v, xi, 0), t1 = face_tangent(v, xi, 1);
            Tensor<2, 3>       J;
            for (unsigned int c = 0; c < 3; ++c)
              {
                J[c][0] = t0[c];
                J[c][1] = t1[c];
                J[c][2] = n[c];
              }
            const Tensor<2, 3> inverse = invert(J);
            for (unsigned int k = 0; k < 2; ++k)
              (*gradient)[k] = (xi[k] < 0 || xi[k] > 1) ? Tensor<1, 3>() : inverse[k];
          }
        for (unsigned int k = 0; k < 2; ++k)
          xi[k] = std::min(1., std::max(0., xi[k]));
        return xi;
      }

      double
      signed_area(const std::vector<Point2> &polygon)
      {
        double area = 0;
        for (unsigned int i = 0; i < polygon.size(); ++i)
          {
            const Point2 &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
            area += p[0] * q[1] - q[0] * p[1];
          }
        return area / 2;
      }

      /// Sutherland-Hodgman: @p subject clipped by the convex polygon @p clip,
      /// both counter-clockwise.
      std::vector<Point2>
      clip_polygon(std::vector<Point2> subject, const std::vector<Point2> &clip)
      {
        for (unsigned int i = 0; i < clip.size() && !subject.empty(); ++i)
          {
            const Point2 &a = clip[i], &b = clip[(i + 1) % clip.size()];
            const auto side = [&](const Point2 &p) {
              return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
            };
            std::vector<Point2> kept;
            for (unsigned int k = 0; k < subject.size(); ++k)
              {
                const Point2 &p = subject[k], &q = subject[(k + 1) % subject.size()];
                const double  sp = side(p), sq = side(q);
                if (sp >= 0)
                  kept.push_back(p);
                if ((sp >= 0) != (sq >= 0))
                  {
                    const double t = sp / (sp - sq);
                    kept.push_back({{p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])}});
                  }
              }
            subject = std::move(kept);
          }
        return subject;
      }

      /// The polygon without vertices closer than @p tolerance to the one
      /// before (clipping repeats a vertex that lies on a clip edge).
      std::vector<Point2>
      without_duplicates(const std::vector<Point2> &polygon, const double tolerance)
      {
        std::vector<Point2> result;
        for (const Point2 &p : polygon)
          if (result.empty() || std::hypot(p[0] - result.back()[0],
                                           p[1] - result.back()[1]) > tolerance)
            result.push_back(p);
        while (result.size() > 1 &&
               std::hypot(result[0][0] - result.back()[0],
                          result[0][1] - result.back()[1]) <= tolerance)
          result.pop_back();
        return result;
      }

      /// Radon's 7-point rule on the reference triangle (degree 5; the
      /// weights add up to its area, 1/2): (r, s, weight).
      std::vector<std::array<double, 3>>
      triangle_rule()
      {
        std::vector<std::array<double, 3>> rule = {{{1. / 3, 1. / 3, 9. / 80}}};
        for (const double sign : {1., -1.})
          {
            const double a = (6 - sign * std::sqrt(15.)) / 21;
            const double w = (155 - sign * std::sqrt(15.)) / 2400;
            rule.push_back({{a, a, w}});
            rule.push_back({{1 - 2 * a, a, w}});
            rule.push_back({{a, 1 - 2 * a, w}});
          }
        return rule;
      }



      FaceIntegrals<2>
      integrals_2d(const FaceVertices<2>          &slave,
                   const Tensor<1, 2>             &normal,
                   const FaceVertices<2>          &master,
                   const MasterNormals<2>         *master_normals,
                   const bool                      revolved)
      {
        FaceIntegrals<2> result{Table<2, double>(2, 2), Table<2, Tensor<1, 2>>(2, 2)};
        Table<2, double> &M = result.M;
        const Tensor<1, 2> edge   = slave[1] - slave[0];
        const double       length = edge.norm();
        // Where the line through master vertex b meets the slave's: along
        // b's vertex normal where the master has them, else along the
        // slave's normal.
        const auto slave_parameter = [&](const unsigned int b) {
          const Tensor<1, 2> &direction = master_normals ? (*master_normals)[b] : normal;
          return cross_2d(master[b] - slave[0], direction) / cross_2d(edge, direction);
        };
        const double s0 = slave_parameter(0), s1 = slave_parameter(1);
        const double low = std::max(0., std::min(s0, s1));
        const double high = std::min(1., std::max(s0, s1));
        const double across = cross_2d(master[1] - master[0], normal);
        if (high - low <= 1e-12 || std::abs(across) < 1e-14 * length ||
            std::abs(s1 - s0) < 1e-14)
          return result;
        const Table<2, double> A = dual_coefficients<2>(slave, revolved);
        // d t / d x across the normal: the master's N_1 = t, N_0 = 1 - t.
        const Tensor<1, 2> t_gradient({normal[1] / across, -normal[0] / across});
        const QGauss<1>        gauss(2);
        for (unsigned int q = 0; q < gauss.size(); ++q)
          {
            const double   s   = low + gauss.point(q)[0] * (high - low);
            const Point<2> x   = slave[0] + s * edge;
            const double   JxW = gauss.weight(q) * (high - low) * length *
                               (revolved ? 2 * numbers::PI * x[0] : 1.);
            // The master's parameter: along the normal, or linear between
            // the vertices' projections along their own normals.
            const double t = master_normals ? (s - s0) / (s1 - s0) :
                                              cross_2d(x - master[0], normal) / across;
            const auto     Ns  = shape_values<2>(Point<1>(s));
            const auto     Nm  = shape_values<2>(Point<1>(std::min(1., std::max(0., t))));
            const bool     inside = t > 0 && t < 1;
            for (unsigned int a = 0; a < 2; ++a)
              {
                const double phi = A(a, 0) * Ns[0] + A(a, 1) * Ns[1];
                for (unsigned int b = 0; b < 2; ++b)
                  M(a, b) += JxW * phi * Nm[b];
                if (inside)
                  {
                    result.slide(a, 1) += JxW * phi * t_gradient;
                    result.slide(a, 0) -= JxW * phi * t_gradient;
                  }
              }
          }
        return result;
      }



      FaceIntegrals<3>
      integrals_3d(const FaceVertices<3>  &slave,
                   const Tensor<1, 3>     &normal,
                   const FaceVertices<3>  &master_face,
                   const MasterNormals<3> *master_normals)
      {
        FaceIntegrals<3> result{Table<2, double>(4, 4), Table<2, Tensor<1, 3>>(4, 4)};
        Table<2, double> &M = result.M;
        const Point<3>   centre = face_point<3>(slave, Point<2>(0.5, 0.5));
        Tensor<1, 3>     e1     = face_tangent(slave, Point<2>(0.5, 0.5), 0);
        e1 -= (e1 * normal) * normal;
        e1 /= e1.norm();
        const Tensor<1, 3> e2        = cross_product_3d(normal, e1);
        // With the master's vertex normals, each vertex moved along its
        // own normal onto the plane through the slave's centre normal to
        // @p normal: two faces that share an edge then share its image,
        // and the images of a faceted surface tile the slave face without
        // gaps or overlaps (along each face's own normal they would not).
        FaceVertices<3> master = master_face;
        if (master_normals != nullptr)
          for (unsigned int b = 0; b < 4; ++b)
            master[b] -= ((master[b] - centre) * normal) /
                         ((*master_normals)[b] * normal) * (*master_normals)[b];
        const auto         in_plane  = [&](const Point<3> &p) {
          return Point2{{(p - centre) * e1, (p - centre) * e2}};
        };
        // Vertices in cyclic order (deal.II numbers them lexicographically),
        // counter-clockwise about the slave normal.
        const auto polygon = [&](const FaceVertices<3> &v) {
          std::vector<Point2> p = {
            in_plane(v[0]), in_plane(v[1]), in_plane(v[3]), in_plane(v[2])};
          if (signed_area(p) < 0)
            std::reverse(p.begin(), p.end());
          return p;
        };
        const std::vector<Point2> slave_polygon = polygon(slave);
        const double              slave_area    = signed_area(slave_polygon);
        const double scale = std::sqrt(slave_area);
        const std::vector<Point2> overlap = without_duplicates(
          clip_polygon(slave_polygon, polygon(master)), 1e-12 * scale);
        if (overlap.size() < 3 || signed_area(overlap) <= 1e-12 * slave_area)
          return result;

        const Table<2, double> A = dual_coefficients<3>(slave);
        Point2                 c = {{0, 0}};
        for (const Point2 &p : overlap)
          for (unsigned int k = 0; k < 2; ++k)
            c[k] += p[k] / overlap.size();
        static const auto rule = triangle_rule();
        for (unsigned int i = 0; i < overlap.size(); ++i)
          {
            const Point2 &p = overlap[i], &q = overlap[(i + 1) % overlap.size()];
            const double  area = ((p[0] - c[0]) * (q[1] - c[1]) -
                                 (q[0] - c[0]) * (p[1] - c[1])) / 2;
            for (const auto &[r, s, weight] : rule)
              {
                const double u = c[0] + r * (p[0] - c[0]) + s * (q[0] - c[0]);
                const double v = c[1] + r * (p[1] - c[1]) + s * (q[1] - c[1]);
                const Point<3> X   = centre + u * e1 + v * e2;
                const auto     Ns  = shape_values<3>(inverse_map(slave, X, normal));
                std::array<Tensor<1, 3>, 2> xi_gradient;
                const Point<2> xi  = inverse_map(master, X, normal, &xi_gradient);
                const auto     Nm  = shape_values<3>(xi);
                const double   JxW = 2 * area * weight;
                // grad N_b = sum_k dN_b / dxi_k grad xi_k.
                const double dN[2][4] = {{-(1 - xi[1]), 1 - xi[1], -xi[1], xi[1]},
                                         {-(1 - xi[0]), -xi[0], 1 - xi[0], xi[0]}};
                for (unsigned int a = 0; a < 4; ++a)
                  {
                    double phi = 0;
                    for (unsigned int b = 0; b < 4; ++b)
                      phi += A(a, b) * Ns[b];
                    for (unsigned int b = 0; b < 4; ++b)
                      {
                        M(a, b) += JxW * phi * Nm[b];
                        result.slide(a, b) +=
                          JxW * phi * (dN[0][b] * xi_gradient[0] + dN[1][b] * xi_gradient[1]);
                      }
                  }
              }
          }
        return result;
      }
    } // namespace



    template <int dim>
    std::array<double, GeometryInfo<dim - 1>::vertices_per_cell>
    shape_values(const Point<dim - 1> &xi)
    {
      if constexpr (dim == 2)
        return {{1 - xi[0], xi[0]}};
      else
        return {{(1 - xi[0]) * (1 - xi[1]),
                 xi[0] * (1 - xi[1]),
                 (1 - xi[0]) * xi[1],
                 xi[0] * xi[1]}};
    }



    template <int dim>
    Table<2, double>
    dual_coefficients(const FaceVertices<dim> &slave, const bool revolved)
    {
      constexpr unsigned int n = GeometryInfo<dim - 1>::vertices_per_cell;
      const QGauss<dim - 1>  gauss(3);
      FullMatrix<double>     mass(n, n);
      std::array<double, n>  lumped{};
      for (unsigned int q = 0; q < gauss.size(); ++q)
        {
          double jacobian;
          if constexpr (dim == 2)
            jacobian = slave[0].distance(slave[1]);
          else
            jacobian = cross_product_3d(face_tangent(slave, gauss.point(q), 0),
                                        face_tangent(slave, gauss.point(q), 1))
                         .norm();
          const auto N  = shape_values<dim>(gauss.point(q));
          double     dx = gauss.weight(q) * jacobian;
          // The measure of revolution's weight r (its 2 pi cancels in A).
          if constexpr (dim == 2)
            if (revolved)
              dx *= slave[0][0] + gauss.point(q)[0] * (slave[1][0] - slave[0][0]);
          for (unsigned int a = 0; a < n; ++a)
            {
              lumped[a] += N[a] * dx;
              for (unsigned int b = 0; b < n; ++b)
                mass(a, b) += N[a] * N[b] * dx;
            }
        }
      mass.gauss_jordan();
      Table<2, double> A(n, n);
      for (unsigned int a = 0; a < n; ++a)
        for (unsigned int b = 0; b < n; ++b)
          A(a, b) = lumped[a] * mass(a, b);
      return A;
    }



    template <int dim>
    FaceIntegrals<dim>
    face_integrals(const FaceVertices<dim>  &slave,
                   const Tensor<1, dim>     &slave_normal,
                   const FaceVertices<dim>  &master,
                   const MasterNormals<dim> *master_normals,
                   const bool                revolved)
    {
      if constexpr (dim == 2)
        return integrals_2d(slave, slave_normal, master, master_normals, revolved);
      else
        return integrals_3d(slave, slave_normal, master, master_normals);
    }

    template <int dim>
    Tensor<1, dim>
    unit_normal(const FaceVertices<dim> &x)
    {
      Tensor<1, dim> n;
      if constexpr (dim == 2)
        {
          n[0] = x[1][1] - x[0][1];
          n[1] = x[0][0] - x[1][0];
        }
      else
        n = cross_product_3d(0.5 * (x[1] - x[0] + x[3] - x[2]),
                             0.5 * (x[2] - x[0] + x[3] - x[1]));
      return n / n.norm();
    }



    template <int dim>
    std::array<Tensor<2, dim>, GeometryInfo<dim - 1>::vertices_per_cell>
    unit_normal_derivatives(const FaceVertices<dim> &x)
    {
      // n = N / |N|: dn = (I - n n^T) dN / |N|, N linear in the vertices
      // in 2D and a cross product of two mean edges in 3D.
      std::array<Tensor<2, dim>, GeometryInfo<dim - 1>::vertices_per_cell> D;
      Tensor<1, dim> N;
      if constexpr (dim == 2)
        {
          N = Tensor<1, dim>({x[1][1] - x[0][1], x[0][0] - x[1][0]});
          D[1][0][1] = 1;
          D[1][1][0] = -1;
          D[0]       = -D[1];
        }
      else
        {
          const Tensor<1, dim> a = 0.5 * (x[1] - x[0] + x[3] - x[2]);
          const Tensor<1, dim> b = 0.5 * (x[2] - x[0] + x[3] - x[1]);
          N                      = cross_product_3d(a, b);
          // d(a x b) = -[b]x da + [a]x db, [v]x w = v x w.
          const auto cross_matrix = [](const Tensor<1, dim> &v) {
            return Tensor<2, dim>(
              {{0., -v[2], v[1]}, {v[2], 0., -v[0]}, {-v[1], v[0], 0.}});
          };
          const double along_a[4] = {-0.5, 0.5, -0.5, 0.5};
          const double along_b[4] = {-0.5, -0.5, 0.5, 0.5};
          for (unsigned int v = 0; v < 4; ++v)
            D[v] = -along_a[v] * cross_matrix(b) + along_b[v] * cross_matrix(a);
        }
      const double         length = N.norm();
      const Tensor<1, dim> n      = N / length;
      const Tensor<2, dim> across =
        (Tensor<2, dim>(unit_symmetric_tensor<dim>()) - outer_product(n, n)) / length;
      for (auto &D_v : D)
        D_v = across * D_v;
      return D;
    }



    template <int dim>
    Tensor<2, dim>
    normal_gradient(const FaceVertices<dim>                                             &x,
                    const std::array<Tensor<1, dim>, GeometryInfo<dim - 1>::vertices_per_cell> &normals)
    {
      // The surface gradient of each shape function at the centre,
      // J (J^T J)^-1 grad_xi N with J the face's tangents there.
      constexpr unsigned int n_vertices = GeometryInfo<dim - 1>::vertices_per_cell;
      std::array<Tensor<1, dim>, n_vertices> gradients;
      if constexpr (dim == 2)
        {
          const Tensor<1, dim> a = x[1] - x[0];
          gradients[0]           = -a / a.norm_square();
          gradients[1]           = a / a.norm_square();
        }
      else
        {
          const Tensor<1, dim> a   = 0.5 * (x[1] - x[0] + x[3] - x[2]);
          const Tensor<1, dim> b   = 0.5 * (x[2] - x[0] + x[3] - x[1]);
          const double         aa  = a * a, ab = a * b, bb = b * b;
          const double         det = aa * bb - ab * ab;
          const double d_xi[4]  = {-0.5, 0.5, -0.5, 0.5};
          const double d_eta[4] = {-0.5, -0.5, 0.5, 0.5};
          for (unsigned int v = 0; v < n_vertices; ++v)
            {
              // (J^T J)^-1 (d_xi, d_eta), then J times it.
              const double p = (bb * d_xi[v] - ab * d_eta[v]) / det;
              const double q = (aa * d_eta[v] - ab * d_xi[v]) / det;
              gradients[v]   = p * a + q * b;
            }
        }
      Tensor<2, dim> G;
      for (unsigned int v = 0; v < n_vertices; ++v)
        G += outer_product(normals[v], gradients[v]);
      return G;
    }

    template std::array<double, 2>
    shape_values<2>(const Point<1> &);
    template std::array<double, 4>
    shape_values<3>(const Point<2> &);
    template Table<2, double>
    dual_coefficients<2>(const FaceVertices<2> &, const bool);
    template Table<2, double>
    dual_coefficients<3>(const FaceVertices<3> &, const bool);
    template FaceIntegrals<2>
    face_integrals<2>(const FaceVertices<2> &,
                      const Tensor<1, 2> &,
                      const FaceVertices<2> &,
                      const MasterNormals<2> *,
                      const bool);
    template FaceIntegrals<3>
    face_integrals<3>(const FaceVertices<3> &,
                      const Tensor<1, 3> &,
                      const FaceVertices<3> &,
                      const MasterNormals<3> *,
                      const bool);
    template Tensor<1, 2>
    unit_normal<2>(const FaceVertices<2> &);
    template Tensor<1, 3>
    unit_normal<3>(const FaceVertices<3> &);
    template std::array<Tensor<2, 2>, 2>
    unit_normal_derivatives<2>(const FaceVertices<2> &);
    template std::array<Tensor<2, 3>, 4>
    unit_normal_derivatives<3>(const FaceVertices<3> &);
    template Tensor<2, 2>
    normal_gradient<2>(const FaceVertices<2> &, const std::array<Tensor<1, 2>, 2> &);
    template Tensor<2, 3>
    normal_gradient<3>(const FaceVertices<3> &, const std::array<Tensor<1, 3>, 4> &);
  } // namespace MortarSegments
} // namespace FrictionalContact
