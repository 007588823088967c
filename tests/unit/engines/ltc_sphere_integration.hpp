#pragma once
// Test support: adaptive cubature of a function of direction over the whole sphere, in the coordinates
// (u, phi) = (cos theta, azimuth) where d omega = du d phi, so no Jacobian hides in the integrand; the
// sphere is split into 4 x 4 initial tiles. Independent of the engine's own sampling code.
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "pbrfit/integrate/adaptive_cubature.hpp"
#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::test {

inline Vector3 sphere_direction(double u, double phi) {
  const double radius = std::sqrt(std::max(0.0, 1.0 - u * u));
  return {radius * std::cos(phi), radius * std::sin(phi), u};
}

// Integral over the sphere of f(w), f returning std::array<double, Comp>.
template <int Comp, class F>
integrate::AdaptiveResult<Comp> integrate_over_sphere(const F& f, double tolerance,
                                                      std::size_t max_evaluations = 4'000'000) {
  std::vector<integrate::Box<2>> tiles;
  constexpr int splits = 4;
  for (int i = 0; i < splits; ++i) {
    for (int j = 0; j < splits; ++j) {
      const double u0 = -1.0 + 2.0 * i / splits;
      const double phi0 = 2.0 * std::numbers::pi * j / splits;
      tiles.push_back({{u0, phi0}, {u0 + 2.0 / splits, phi0 + 2.0 * std::numbers::pi / splits}});
    }
  }
  const auto integrand = [&](const std::array<double, 2>& x) { return f(sphere_direction(x[0], x[1])); };
  return integrate::integrate_adaptive<2, Comp>(integrand, std::span<const integrate::Box<2>>(tiles),
                                                integrate::AdaptiveOptions{tolerance, max_evaluations});
}

}  // namespace pbrfit::test
