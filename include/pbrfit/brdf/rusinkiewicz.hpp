#pragma once
// Rusinkiewicz's half/difference coordinates of a pair of directions (Rusinkiewicz 1998), as the MERL
// database tabulates isotropic BRDFs: with h = normalize(wi + wo) at (theta_h, phi_h), the difference
// vector d = R_y(-theta_h) R_z(-phi_h) wi at (theta_d, phi_d). Directions are unit vectors in the shading
// frame (normal +z).
//
// Invariants: from_half_diff(to_half_diff(wi, wo)) gives (wi, wo) back up to rounding for wi != -wo;
// theta_h, theta_d in [0, pi], phi_h, phi_d in (-pi, pi]; wo is wi reflected about h.
#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::brdf {

struct HalfDiff {
  double theta_h = 0.0, phi_h = 0.0;
  double theta_d = 0.0, phi_d = 0.0;
};

struct DirectionPair {
  Vector3 wi = Vector3::UnitZ();
  Vector3 wo = Vector3::UnitZ();
};

HalfDiff to_half_diff(const Vector3& wi, const Vector3& wo);
DirectionPair from_half_diff(const HalfDiff& angles);

}  // namespace pbrfit::brdf
