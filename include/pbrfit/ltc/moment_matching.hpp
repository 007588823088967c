#pragma once
// A fast starting LTC for a set of unit directions, by matching moments. The frame's z is the targets' mean
// direction; in that frame the 2 x 2 second moment of the tangential components (x, y) is diagonalized, and
// each principal axis gets the scale m at which the isotropic LTC diag(m, m, 1) has the same second moment
// along an axis:
//   isotropic_second_moment(m) = E[x^2] = (m^2 / 2) (1 / k - ln(1 + k) / k^2),   k = m^2 - 1,
// which increases from 0 (m -> 0) through 1/4 (m = 1, the cosine) towards 1/2 (m -> infinity).
// The start is M0 = [frame] [principal axes] diag(m1, m2, 1).
//
// Invariants: M0 is invertible (each m is clamped to [1e-4, 1e3]); for the samples of diag(m, m, 1) rotated by R
// it tends to that LTC (up to the equivalences of distribution.hpp) as the sample count grows; deterministic.
#include <span>

#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::ltc {

double isotropic_second_moment(double m);

Matrix3 moment_matched_ltc(std::span<const Vector3> targets);

}  // namespace pbrfit::ltc
