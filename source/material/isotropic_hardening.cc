#include <frictional_contact/base/input.h>
#include <frictional_contact/material/isotropic_hardening.h>

#include <cmath>

namespace FrictionalContact
{
  IsotropicHardening
  IsotropicHardening::linear(const double initial_yield_stress, const double modulus)
  {
    IsotropicHardening h;
    h.initial_stress = initial_yield_stress;
    h.modulus        = modulus;
    return h;
  }



  IsotropicHardening
  IsotropicHardening::voce(const double initial_yield_stress,
                           const double saturation_stress,
                           const double rate,
                           const double modulus)
  {
    IsotropicHardening h = linear(initial_yield_stress, modulus);
    h.kind               = Kind::voce;
    h.saturation_stress  = saturation_stress;
    h.rate               = rate;
    return h;
  }



  IsotropicHardening
  IsotropicHardening::flow_curve(std::vector<std::pair<double, double>> points)
  {
    IsotropicHardening h;
    h.kind   = Kind::flow_curve;
    h.points = std::move(points);
    return h;
  }



  std::string
  IsotropicHardening::flow_curve_problem(const std::vector<std::pair<double, double>> &points)
  {
    if (points.empty())
      return "no point";
    if (points.front().first != 0)
      return "its first plastic strain is " + Input::to_text(points.front().first) +
             ", not 0 (the curve starts where the material first yields)";
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        if (!(points[k].second > 0))
          return "the yield stress " + Input::to_text(points[k].second) +
                 " at plastic strain " + Input::to_text(points[k].first) +
                 " is not > 0";
        if (k > 0 && !(points[k].first > points[k - 1].first))
          return "its plastic strains do not increase (" +
                 Input::to_text(points[k - 1].first) + " then " +
                 Input::to_text(points[k].first) + ")";
      }
    return "";
  }



  double
  IsotropicHardening::yield_stress(const double alpha) const
  {
    switch (kind)
      {
        case Kind::linear:
          return initial_stress + modulus * alpha;
        case Kind::voce:
          return initial_stress +
                 (saturation_stress - initial_stress) * (1. - std::exp(-rate * alpha)) +
                 modulus * alpha;
        case Kind::flow_curve:
          {
            const unsigned int k = segment_end(alpha);
            if (k == points.size())
              return points.back().second;
            const auto &[a0, s0] = points[k - 1];
            return s0 + segment_slope(k) * (alpha - a0);
          }
      }
    return 0;
  }



  double
  IsotropicHardening::slope(const double alpha) const
  {
    switch (kind)
      {
        case Kind::linear:
          return modulus;
        case Kind::voce:
          return (saturation_stress - initial_stress) * rate * std::exp(-rate * alpha) +
                 modulus;
        case Kind::flow_curve:
          {
            const unsigned int k = segment_end(alpha);
            return k == points.size() ? 0. : segment_slope(k);
          }
      }
    return 0;
  }



  unsigned int
  IsotropicHardening::segment_end(const double alpha) const
  {
    unsigned int k = 1;
    while (k < points.size() && !(alpha < points[k].first))
      ++k;
    return k;
  }



  double
  IsotropicHardening::segment_slope(const unsigned int k) const
  {
    return (points[k].second - points[k - 1].second) / (points[k].first - points[k - 1].first);
  }



  std::string
  IsotropicHardening::describe() const
  {
    switch (kind)
      {
        case Kind::linear:
          return Input::to_text(modulus);
        case Kind::voce:
          return "Voce to " + Input::to_text(saturation_stress) + " at rate " +
                 Input::to_text(rate) + " plus " + Input::to_text(modulus);
        case Kind::flow_curve:
          return "a flow curve of " + std::to_string(points.size()) + " points";
      }
    return "";
  }
} // namespace FrictionalContact
