#pragma once
// The box an optimizer searches: lower[d] <= x[d] <= upper[d] for every dimension d.
//
// Invariants (checked by validate(), which every optimizer calls first): lower and upper have the same,
// non-zero size; every bound is finite; lower[d] <= upper[d]. A dimension with lower == upper is fixed:
// optimizers keep it at that value and spend no evaluations exploring it.
#include <cstddef>
#include <span>
#include <vector>

namespace pbrfit::optimize {

struct Bounds {
  std::vector<double> lower;
  std::vector<double> upper;

  std::size_t dimension() const { return lower.size(); }
  double width(std::size_t d) const { return upper[d] - lower[d]; }
  bool is_fixed(std::size_t d) const { return upper[d] == lower[d]; }
};

// The same interval [lower, upper] in every one of `dimension` dimensions.
Bounds uniform_bounds(std::size_t dimension, double lower, double upper);

// Throws std::invalid_argument when the invariants above do not hold.
void validate(const Bounds& bounds);

bool contains(const Bounds& bounds, std::span<const double> x);

// Moves every coordinate of x onto the nearest point of the box.
void clamp_into(const Bounds& bounds, std::span<double> x);

}  // namespace pbrfit::optimize
