#pragma once
// The two-dimensional Halton sequence (radical inverses in bases 2 and 3), a deterministic
// low-discrepancy point set for quasi-Monte Carlo estimates (Pesce & Iwanicki 2015, section 7.3).
//
// Invariants: point i is a pure function of i; both coordinates lie in [0, 1); the first n points fill
// [0,1)^2 with discrepancy O(log^2 n / n). Point 0 is skipped (it is the corner (0, 0)).
#include <array>
#include <cstddef>
#include <vector>

namespace pbrfit::integrate {

double radical_inverse(unsigned base, std::size_t index);

// Points 1..count of the sequence.
std::vector<std::array<double, 2>> halton_points(std::size_t count);

}  // namespace pbrfit::integrate
