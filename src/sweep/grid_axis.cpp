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

std::string invalid_reason(const GridAxis& axis) {
  const std::string name = "axis '" + axis.name + "' ";
  if (!std::isfinite(axis.lower) || !std::isfinite(axis.upper)) return name + "has a non-finite bound";
  if (axis.count == 0) return name + "has no samples";
  if (axis.lower > axis.upper) return name + "has lower > upper";
  if (axis.lower == axis.upper && axis.count != 1) return name + "is a single value but has several samples";
  if (axis.lower < axis.upper && axis.placement == Placement::edges && axis.count < 2)
    return name + "needs at least 2 samples at cell edges";
  return "";
}

void validate(const GridAxis& axis) {
  if (const std::string reason = invalid_reason(axis); !reason.empty()) throw std::invalid_argument("sweep: " + reason);
}

}  // namespace pbrfit::sweep
