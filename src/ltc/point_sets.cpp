#include "pbrfit/ltc/point_sets.hpp"

#include <cmath>
#include <numbers>

namespace pbrfit::ltc {
namespace {

constexpr double inverse_golden_ratio = 0.6180339887498948482;  // 1 / phi = phi - 1

double fractional_part(double x) { return x - std::floor(x); }

}  // namespace

std::vector<std::array<double, 2>> golden_lattice(std::size_t count) {
  std::vector<std::array<double, 2>> points(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double centre = static_cast<double>(i) + 0.5;
    points[i] = {centre / static_cast<double>(count), fractional_part(centre * inverse_golden_ratio)};
  }
  return points;
}

std::vector<Vector3> axis_directions(std::size_t count) {
  std::vector<Vector3> axes(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double centre = static_cast<double>(i) + 0.5;
    const double z = 1.0 - centre / static_cast<double>(count);
    const double radius = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = 2.0 * std::numbers::pi * fractional_part(centre * inverse_golden_ratio);
    axes[i] = Vector3(radius * std::cos(phi), radius * std::sin(phi), z);
  }
  return axes;
}

}  // namespace pbrfit::ltc
