#pragma once
// The clamped cosine D_o(w) = max(0, w.z) / pi on the unit sphere: the base distribution of every LTC.
//
// Invariants: D_o integrates to 1 over the sphere; sample_clamped_cosine maps [0, 1)^2 onto the upper
// hemisphere with density exactly D_o, continuously in (u1, u2) (u1 = sin^2 theta, u2 = phi / 2 pi);
// cosine_samples(n) is that map applied to golden_lattice(n) (point_sets.hpp): n fixed directions, z > 0.
#include <algorithm>
#include <cstddef>
#include <numbers>
#include <vector>

#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::ltc {

inline double clamped_cosine(const Vector3& w) { return std::max(0.0, w.z()) * std::numbers::inv_pi; }

Vector3 sample_clamped_cosine(double u1, double u2);

std::vector<Vector3> cosine_samples(std::size_t count);

}  // namespace pbrfit::ltc
