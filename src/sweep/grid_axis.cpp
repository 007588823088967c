#include "pbrfit/sweep/grid_axis.hpp"

#include <cmath>
#include <stdexcept>

namespace pbrfit::sweep {

double GridAxis::value(std::size_t index) const {
  if (lower == upper) return lower;
  const double width = upper - lower;
  if (placement == Placement::centres) return lower + (double(index) + 0.5) * width / double(count);
  if (index + 1 == count) return upper;  // exact end point, whatever the rounding
  return lower + double(index) * width / double(count - 1);
}

std::vector<double> GridAxis::values() const {
  std::vector<double> out(count);
  for (std::size_t i = 0; i < count; ++i) out[i] = value(i);
  return out;
}

GridAxis GridAxis::with_count(std::size_t new_count) const {
  GridAxis axis = *this;
  axis.count = new_count;
  return axis;
}

void validate(const GridAxis& axis) {
  const auto fail = [&](const std::string& why) {
    throw std::invalid_argument("sweep: axis '" + axis.name + "' " + why);
  };
  if (!std::isfinite(axis.lower) || !std::isfinite(axis.upper)) fail("has a non-finite bound");
  if (axis.count == 0) fail("has no samples");
  if (axis.lower > axis.upper) fail("has lower > upper");
  if (axis.lower == axis.upper && axis.count != 1) fail("is a single value but has several samples");
  if (axis.lower < axis.upper && axis.placement == Placement::edges && axis.count < 2)
    fail("needs at least 2 samples at cell edges");
}

}  // namespace pbrfit::sweep
