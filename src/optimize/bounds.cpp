#include "pbrfit/optimize/bounds.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pbrfit::optimize {

Bounds uniform_bounds(std::size_t dimension, double lower, double upper) {
  return Bounds{std::vector<double>(dimension, lower), std::vector<double>(dimension, upper)};
}

void validate(const Bounds& bounds) {
  if (bounds.lower.empty() || bounds.lower.size() != bounds.upper.size()) {
    throw std::invalid_argument("optimize: bounds need matching, non-empty lower and upper");
  }
  for (std::size_t d = 0; d < bounds.dimension(); ++d) {
    if (!std::isfinite(bounds.lower[d]) || !std::isfinite(bounds.upper[d]) || bounds.lower[d] > bounds.upper[d]) {
      throw std::invalid_argument("optimize: bounds must be finite with lower <= upper");
    }
  }
}

bool contains(const Bounds& bounds, std::span<const double> x) {
  for (std::size_t d = 0; d < bounds.dimension(); ++d) {
    if (!(x[d] >= bounds.lower[d] && x[d] <= bounds.upper[d])) return false;
  }
  return true;
}

void clamp_into(const Bounds& bounds, std::span<double> x) {
  for (std::size_t d = 0; d < bounds.dimension(); ++d) x[d] = std::clamp(x[d], bounds.lower[d], bounds.upper[d]);
}

}  // namespace pbrfit::optimize
