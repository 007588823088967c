#pragma once
// A specular lobe projected onto a plane (Pesce & Iwanicki 2015, section 8: parallax-corrected probes).
// The lobe is the cosine-weighted GGX response at normal view, rho_alpha(w) = ggx_cosine_weighted(alpha,
// axis, w) in the frame of its axis, emitted from `origin` above the plane z = 0 towards it. Projected, it
// becomes a density over the plane (per unit area) that keeps the lobe's energy:
//   P(x, y) = rho_alpha(w) cos(w, plane normal) / r^2 = rho_alpha(w) origin.z / r^3,
//   w = (p - origin) / r, r = |p - origin|, p = (x, y, 0).
// Invariants: origin.z > 0, unit axis pointing down (axis.z < 0), alpha > 0 (the caller's duty); P >= 0.
#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::brdf {

struct ProjectedLobe {
  double alpha = 0.1;
  Vector3 origin = Vector3::UnitZ();
  Vector3 axis = -Vector3::UnitZ();

  double density(double x, double y) const;
};

// The lobe perpendicular to the plane at height `distance` above (centre_x, centre_y).
ProjectedLobe perpendicular_lobe(double alpha, double distance, double centre_x = 0.0, double centre_y = 0.0);

// The lobe whose axis makes `angle` with the plane normal (tilted towards +x) and hits the plane at the
// origin after travelling `distance`: origin = (-distance sin angle, 0, distance cos angle).
ProjectedLobe tilted_lobe(double alpha, double angle, double distance);

}  // namespace pbrfit::brdf
