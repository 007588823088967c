#pragma once
// Projection of a function of direction onto the nine real SH (spherical_harmonics.hpp) by adaptive
// cubature (integrate/direction_domain.hpp) over the zone z in [z_min, 1]: the nine integrals of
// f(w) Y_i(w) dw are one 9-component integral, so they share samples and one error estimate (the largest
// component error, summed over tiles).
#include <cstddef>
#include <functional>

#include "pbrfit/brdf/spherical_harmonics.hpp"
#include "pbrfit/integrate/adaptive_cubature.hpp"

namespace pbrfit::brdf {

struct ShProjection {
  ShCoefficients sh{};
  double error_estimate = 0.0;
  std::size_t evaluations = 0;
  bool converged = false;
};

// z_min = 0 for a lobe that vanishes below the horizon, -1 for the whole sphere.
ShProjection project_to_sh(const std::function<double(const Vector3&)>& f, double z_min,
                           const integrate::AdaptiveOptions& options);

}  // namespace pbrfit::brdf
