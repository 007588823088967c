#include "pbrfit/integrate/halton.hpp"

namespace pbrfit::integrate {

double radical_inverse(unsigned base, std::size_t index) {
  const double inverse_base = 1.0 / base;
  double digit_weight = inverse_base;
  double value = 0.0;
  while (index > 0) {
    value += static_cast<double>(index % base) * digit_weight;
    index /= base;
    digit_weight *= inverse_base;
  }
  return value;
}

std::vector<std::array<double, 2>> halton_points(std::size_t count) {
  std::vector<std::array<double, 2>> points(count);
  for (std::size_t i = 0; i < count; ++i) points[i] = {radical_inverse(2, i + 1), radical_inverse(3, i + 1)};
  return points;
}

}  // namespace pbrfit::integrate
