#pragma once

#include <string>
#include <utility>
#include <vector>

namespace FrictionalContact
{
  /**
   * The uniaxial yield stress of isotropic hardening against the
   * equivalent plastic strain alpha: linear, sigma_0 + H alpha; Voce
   * (saturation), sigma_0 + (sigma_inf - sigma_0)(1 - exp(-delta alpha)) +
   * H alpha; or a measured flow curve, points (alpha_k, sigma_k) from
   * alpha = 0 on, piecewise linear and constant past the last point. Owns
   * the curve; J2 plasticity's return mapping asks it for the stress and
   * the slope.
   */
  class IsotropicHardening
  {
  public:
    static IsotropicHardening
    linear(double initial_yield_stress, double modulus);

    static IsotropicHardening
    voce(double initial_yield_stress, double saturation_stress, double rate, double modulus);

    /// @p points: plastic strains from 0, increasing, and yield stresses > 0
    /// (the caller checks them: flow_curve_problem()).
    static IsotropicHardening
    flow_curve(std::vector<std::pair<double, double>> points);

    /// What is wrong with the points of a flow curve, empty if nothing.
    static std::string
    flow_curve_problem(const std::vector<std::pair<double, double>> &points);

    /// sigma_y(alpha).
    double
    yield_stress(double alpha) const;

    /// d sigma_y / d alpha at alpha (from the right at a point of the curve).
    double
    slope(double alpha) const;

    /// The hardening as J2 plasticity's description names it: the modulus
    /// ("10000") where linear, "Voce to ... at rate ... plus ...", "a flow
    /// curve of 4 points".
    std::string
    describe() const;

  private:
    /// The index of the first point of the flow curve beyond @p alpha
    /// (points.size() past the last point).
    unsigned int
    segment_end(double alpha) const;

    /// The slope of the flow curve between points k - 1 and k.
    double
    segment_slope(unsigned int k) const;

    enum class Kind
    {
      linear,
      voce,
      flow_curve
    };
    Kind   kind                 = Kind::linear;
    /// sigma_0 of the linear and Voce laws (a flow curve has its points).
    double initial_stress       = 0;
    double saturation_stress    = 0;
    double rate                 = 0;
    double modulus              = 0;
    std::vector<std::pair<double, double>> points;
  };
} // namespace FrictionalContact
