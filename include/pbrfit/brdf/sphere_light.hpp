#pragma once
// Ground truth of GGX lit by a uniform spherical light (Pesce & Iwanicki 2015, section 4.1): the light is
// the cap of half-angle gamma around the unit direction `centre` (a sphere of radius sin gamma at distance
// 1), with radiance 1 / (2 pi (1 - cos gamma)), so that its irradiance at normal incidence tends to 1 as
// gamma -> 0 and the response tends to the point light's rho(v, centre):
//   response(v) = (1 / |cap|) integral over the cap of rho(v, l) dl,   rho from ggx_lobe.hpp,
// by adaptive cubature over the cap in its own frame (z' = cos of the angle to the centre in
// [cos gamma, 1]); light below the horizon contributes 0.
//
// Invariants: alpha > 0, 0 < gamma <= pi/2, unit centre (std::invalid_argument otherwise); deterministic;
// the error estimate is absolute, on the response itself.
#include <cstddef>

#include "pbrfit/integrate/adaptive_cubature.hpp"
#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::brdf {

struct SphereLight {
  Vector3 centre = Vector3::UnitZ();  // unit direction to the light's centre
  double half_angle = 0.1;                      // gamma, radians
  double radius() const;                        // sin gamma: the sphere's radius at distance 1
};

// The light at incidence angle theta from the normal, in the x-z plane: centre = (sin theta, 0, cos theta).
SphereLight sphere_light_at(double incidence, double half_angle);

struct SphereLightResponse {
  double value = 0.0;
  double error_estimate = 0.0;
  std::size_t evaluations = 0;
  bool converged = false;
};

SphereLightResponse sphere_light_response(double alpha, const SphereLight& light, const Vector3& view,
                                          const integrate::AdaptiveOptions& options);

}  // namespace pbrfit::brdf
