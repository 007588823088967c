#pragma once
// The objectives of the parallax-corrected probe fits (Pesce & Iwanicki 2015, section 8): how far a
// candidate lobe, perpendicular to the plane, is from a source lobe projected on it (projected_lobe.hpp):
//   squared = integral over the window of (P_source - (scale P_candidate + offset))^2 dA,
// by adaptive cubature. scale and offset let the fit ignore GGX's long tail (the course fits and then
// discards them).
//  - distance study: source perpendicular at `distance`, candidate perpendicular at distance 1, both above
//    the window's centre; the window is the disk of radius `window` (both are radial: a 1-D integral).
//  - angle study: source tilted by `angle` at `distance` (tilted_lobe), candidate perpendicular at the same
//    distance above the point shift * P, P = (-distance sin angle, 0) the foot of the source's origin
//    (shift 0: above the ray's hit point, 1: below the origin); the window is the square
//    [-window, window]^2 around the hit point (symmetric in y: integrated over y >= 0, doubled).
// Invariants: deterministic; squared >= 0 up to the integration error; equal to 0 when the candidate is
// the source (distance 1, or angle 0, with alpha' = alpha, scale 1, offset 0).
#include <cstddef>

#include "pbrfit/integrate/adaptive_cubature.hpp"

namespace pbrfit::brdf {

struct PerpendicularCandidate {
  double alpha = 0.1;   // alpha' of the fitted lobe
  double scale = 1.0;
  double offset = 0.0;
  double shift = 0.0;   // angle study only, in [0, 1]
};

struct ProjectionError {
  double squared = 0.0;
  double error_estimate = 0.0;  // absolute, of `squared`
  std::size_t evaluations = 0;
  bool converged = false;
};

ProjectionError distance_fit_error(double alpha, double distance, const PerpendicularCandidate& candidate,
                                   double window, const integrate::AdaptiveOptions& options);

ProjectionError angle_fit_error(double alpha, double angle, double distance, const PerpendicularCandidate& candidate,
                                double window, const integrate::AdaptiveOptions& options);

}  // namespace pbrfit::brdf
