// Algorithm 3 (projection onto Coulomb's friction cone) against the
// properties of a Euclidean projection onto a closed convex cone, and
// against a brute-force minimiser, on random points.
#include <frictional_contact/solvers/friction_cone.h>

#include <cmath>
#include <iostream>
#include <random>

using namespace FrictionalContact;

namespace
{
  /// argmin |z - s| over the cone, by sampling the cone's boundary rays.
  template <int dim>
  Tensor<1, dim>
  brute_force_projection(const FrictionCone<dim> &cone, const Tensor<1, dim> &s)
  {
    const double   mu   = cone.mu;
    Tensor<1, dim> best = Tensor<1, dim>(); // the apex
    if (cone.contains(s))
      return s;
    auto try_ray = [&](const Tensor<1, dim> &g) {
      const double   t = std::max(0., (s * g) / (g * g));
      Tensor<1, dim> z = t * g;
      if ((z - s).norm() < (best - s).norm())
        best = z;
    };
    auto ray = [&](const double phi) {
      Tensor<1, dim> g;
      g[0] = -1;
      if (dim == 2)
        g[1] = mu * std::cos(phi); // phi in {0, pi}: the wedge's two edges
      else
        {
          g[1] = mu * std::cos(phi);
          g[dim - 1] = mu * std::sin(phi);
        }
      return g;
    };
    if (dim == 2)
      {
        try_ray(ray(0));
        try_ray(ray(M_PI));
        return best;
      }
    // 3D: dense sampling of the angle, then golden-section refinement.
    const unsigned int n   = 3600;
    double             phi = 0, best_distance = 1e300;
    for (unsigned int i = 0; i < n; ++i)
      {
        const double   p = 2 * M_PI * i / n;
        const auto     g = ray(p);
        const double   t = std::max(0., (s * g) / (g * g));
        const double   d = (t * g - s).norm();
        if (d < best_distance)
          best_distance = d, phi = p;
      }
    double a = phi - 2 * M_PI / n, b = phi + 2 * M_PI / n;
    const double golden = (std::sqrt(5.) - 1) / 2;
    auto distance = [&](const double p) {
      const auto   g = ray(p);
      const double t = std::max(0., (s * g) / (g * g));
      return (t * g - s).norm();
    };
    for (unsigned int i = 0; i < 100; ++i)
      {
        const double c = b - golden * (b - a), d = a + golden * (b - a);
        if (distance(c) < distance(d))
          b = d;
        else
          a = c;
      }
    try_ray(ray((a + b) / 2));
    return best;
  }

  template <int dim>
  bool
  check(const double mu, std::mt19937 &random)
  {
    const FrictionCone<dim>                cone(mu);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    const unsigned int                     n_points = 2000;
    bool in_cone = true, idempotent = true, moreau = true, orthogonal = true,
         brute = true, nearest = true;
    for (unsigned int i = 0; i < n_points; ++i)
      {
        Tensor<1, dim> s;
        for (unsigned int d = 0; d < dim; ++d)
          s[d] = uniform(random) * std::pow(10., 3 * uniform(random));
        const double         scale = s.norm();
        const Tensor<1, dim> p     = cone.project(s);
        const Tensor<1, dim> q     = cone.project_onto_dual(-s);
        const Tensor<1, dim> b     = brute_force_projection(cone, s);

        in_cone    = in_cone && cone.contains(p, 1e-14 * scale);
        idempotent = idempotent && (cone.project(p) - p).norm() <= 1e-14 * scale;
        // Moreau: s = P_F(s) - P_F*(-s), with orthogonal parts.
        moreau     = moreau && (s - (p - q)).norm() <= 1e-14 * scale;
        orthogonal = orthogonal && std::abs(p * q) <= 1e-14 * scale * scale;
        brute      = brute && (p - b).norm() <= 1e-6 * scale;
        nearest    = nearest && (p - s).norm() <= (b - s).norm() + 1e-14 * scale;
      }
    const bool ok = in_cone && idempotent && moreau && orthogonal && brute && nearest;
    std::cout << std::boolalpha << "dim " << dim << ", mu " << mu << ", "
              << n_points
              << " points: in cone " << in_cone << ", idempotent " << idempotent
              << ", Moreau decomposition " << moreau << ", orthogonal parts "
              << orthogonal << ", equals brute-force minimiser " << brute
              << ", at least as near " << nearest << std::endl;
    return ok;
  }

  template <int dim>
  bool
  check_states()
  {
    // Free (zero), inside (stick), on the surface (slip), for mu = 0.5.
    const FrictionCone<dim> cone(0.5);
    Tensor<1, dim>          inside, outside;
    inside[0] = outside[0] = -1;
    inside[1]              = 0.2;
    outside[1]             = 2;
    const bool ok = cone.state(Tensor<1, dim>()) == ContactState::free &&
                    cone.state(inside) == ContactState::stick &&
                    cone.state(cone.project(outside)) == ContactState::slip &&
                    FrictionCone<dim>(0).state(inside) == ContactState::slip;
    std::cout << std::boolalpha << "dim " << dim
              << ", states free / stick / slip: " << ok
              << std::endl;
    return ok;
  }
} // namespace

int
main()
{
  std::mt19937 random(2024);
  bool         ok = true;
  for (const double mu : {0., 0.5, 1., 10.})
    {
      ok = check<2>(mu, random) && ok;
      ok = check<3>(mu, random) && ok;
    }
  ok = check_states<2>() && ok;
  ok = check_states<3>() && ok;
  std::cout << (ok ? "all checks passed" : "SOME CHECKS FAILED") << std::endl;
  return ok ? 0 : 1;
}
