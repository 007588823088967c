#pragma once
// One axis of a sweep grid: `count` samples of [lower, upper], at cell edges (lower + i (upper - lower) /
// (count - 1), both ends included) or cell centres (lower + (i + 0.5) (upper - lower) / count).
//
// Invariants (validate() checks them): finite lower < upper, or lower == upper with count 1; count >= 1;
// edges need count >= 2 unless lower == upper. values() is increasing.
#include <cstddef>
#include <string>
#include <vector>

namespace pbrfit::sweep {

enum class Placement { edges, centres };

struct GridAxis {
  std::string name;
  double lower = 0.0;
  double upper = 1.0;
  std::size_t count = 1;
  Placement placement = Placement::edges;

  double value(std::size_t index) const;
  std::vector<double> values() const;
  // The same axis with another sample count (a level of a hierarchy).
  GridAxis with_count(std::size_t new_count) const;
};

// Why the axis cannot be sampled ("axis 'x' has ..."), empty when every invariant holds.
std::string invalid_reason(const GridAxis& axis);
// Throws std::invalid_argument("sweep: " + the reason) when there is one.
void validate(const GridAxis& axis);

}  // namespace pbrfit::sweep
