#pragma once
// Adaptive cubature of a function of a unit direction over a zone of the sphere, z in [z_min, z_max]
// (z = cos theta; [-1, 1] is the whole sphere, [0, 1] the upper hemisphere), in the coordinates (z, phi):
// the measure dw = dz dphi, so the integrand needs no Jacobian and a zonal function is polynomial in z.
//
// Invariants: -1 <= z_min <= z_max <= 1 (caller's duty); the domain starts as azimuth_tiles equal tiles
// in phi (more tiles resolve lobes away from the pole from the start); the result is as deterministic
// as integrate_adaptive.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "pbrfit/integrate/adaptive_cubature.hpp"

namespace pbrfit::integrate {

using UnitDirection = std::array<double, 3>;

inline UnitDirection direction_from(double z, double phi) {
  const double radius = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {radius * std::cos(phi), radius * std::sin(phi), z};
}

// f: std::array<double, Comp>(const UnitDirection&).
template <int Comp, class F>
AdaptiveResult<Comp> integrate_over_directions(const F& f, double z_min, double z_max, int azimuth_tiles,
                                               const AdaptiveOptions& options) {
  std::vector<Box<2>> tiles;
  const double width = 2.0 * std::numbers::pi / azimuth_tiles;
  for (int i = 0; i < azimuth_tiles; ++i) tiles.push_back(Box<2>{{z_min, i * width}, {z_max, (i + 1) * width}});
  const auto integrand = [&f](const std::array<double, 2>& x) { return f(direction_from(x[0], x[1])); };
  return integrate_adaptive<2, Comp>(integrand, std::span<const Box<2>>(tiles), options);
}

}  // namespace pbrfit::integrate
