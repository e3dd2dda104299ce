#pragma once

#include <deal.II/base/tensor.h>

#include <cmath>
#include <limits>

namespace FrictionalContact
{
  using namespace dealii;

  /// The state of a contact candidate node, read off its reaction.
  enum class ContactState
  {
    free  = 0,
    stick = 1,
    slip  = 2
  };

  /**
   * Coulomb's friction cone in Kanno's sign convention: a reaction
   * r = (r_n, r_t) with r_n <= 0 (the obstacle pushes, it never pulls) and
   * |r_t| <= -mu r_n. Component 0 of a vector is normal, the others are
   * tangential; in 2D the cone is a 2D wedge. For mu = 0 the cone is the
   * half-line {r_t = 0, r_n <= 0} (frictionless contact); Kanno's formula
   * would give the whole line there, without the non-adhesion condition.
   */
  template <int dim>
  class FrictionCone
  {
  public:
    explicit FrictionCone(const double mu)
      : mu(mu)
    {}

    /// Algorithm 3 of the paper: the Euclidean projection of @p s onto the cone.
    Tensor<1, dim>
    project(const Tensor<1, dim> &s) const
    {
      return project(s, mu);
    }

    /**
     * Projection onto the dual cone F* = {v : -v_n >= mu |v_t|}, which is
     * the friction cone with coefficient 1/mu (a half-space for mu = 0).
     */
    Tensor<1, dim>
    project_onto_dual(const Tensor<1, dim> &s) const
    {
      return project(s,
                     mu > 0 ? 1. / mu : std::numeric_limits<double>::infinity());
    }

    /// Whether @p r is in the cone, up to @p tolerance (absolute).
    bool
    contains(const Tensor<1, dim> &r, const double tolerance = 0) const
    {
      return r[0] <= tolerance &&
             tangential_norm(r) <= -mu * r[0] + tolerance;
    }

    /**
     * Free if the reaction is zero, slip if it lies on the cone's surface
     * (within @p relative_tolerance of mu |r_n|), stick otherwise. With
     * mu = 0 every node in contact slips.
     */
    ContactState
    state(const Tensor<1, dim> &r, const double relative_tolerance = 1e-8) const
    {
      if (!(r[0] < 0))
        return ContactState::free;
      if (tangential_norm(r) >= (1. - relative_tolerance) * mu * (-r[0]))
        return ContactState::slip;
      return ContactState::stick;
    }

    static double
    tangential_norm(const Tensor<1, dim> &v)
    {
      double sum = 0;
      for (unsigned int d = 1; d < dim; ++d)
        sum += v[d] * v[d];
      return std::sqrt(sum);
    }

    const double mu;

  private:
    static Tensor<1, dim>
    project(const Tensor<1, dim> &s, const double mu)
    {
      const double s_t = tangential_norm(s);
      if (mu == 0) // the half-line r_t = 0, r_n <= 0
        {
          Tensor<1, dim> r;
          r[0] = std::min(s[0], 0.);
          return r;
        }
      if (std::isinf(mu)) // the half-space r_n <= 0
        {
          Tensor<1, dim> r = s;
          r[0]             = std::min(s[0], 0.);
          return r;
        }
      const double lambda_1 = -mu * s[0] - s_t;
      if (lambda_1 >= 0) // s is in the cone
        return s;
      const double lambda_2 = -s[0] + mu * s_t;
      if (lambda_2 <= 0) // s is in the polar cone
        return Tensor<1, dim>();
      // Here s_t > 0: s_t = 0 would give lambda_1 = -mu s_n < 0, so s_n > 0
      // and lambda_2 = -s_n < 0.
      const double   scale = lambda_2 / (1. + mu * mu);
      Tensor<1, dim> r;
      r[0] = -scale;
      for (unsigned int d = 1; d < dim; ++d)
        r[d] = scale * mu * s[d] / s_t;
      return r;
    }
  };
} // namespace FrictionalContact
