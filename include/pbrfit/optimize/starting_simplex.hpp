#pragma once
// The simplex Nelder-Mead starts (and restarts) from: the start point clamped into the box, plus one
// vertex per free dimension d, offset from it along axis d only by relative_steps[d] times the width.
//
// Invariants: every vertex lies in the box; the offsets are non-zero, so the simplex is never degenerate
// in the free dimensions (its edge vectors are a scaled identity). An offset that would leave the box
// goes the other way; when neither side has room for it, it spans the larger side entirely. Steps below
// 1e-12 count as 1e-12, and an offset too small to change the coordinate spans the larger side. Fixed
// dimensions get no vertex: the simplex has (free dimensions + 1) vertices.
#include <span>
#include <vector>

#include "pbrfit/optimize/bounds.hpp"

namespace pbrfit::optimize {

// relative_steps holds one positive step per dimension of the box.
std::vector<std::vector<double>> starting_simplex(const Bounds& bounds, std::span<const double> start,
                                                  std::span<const double> relative_steps);

}  // namespace pbrfit::optimize
