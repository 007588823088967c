#include "pbrfit/render/equirectangular.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "pbrfit/core/bin_index.hpp"

namespace pbrfit::render {
namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;

}  // namespace

LatLong angles_of(const Vector3& d) {
  double phi = std::atan2(d.x(), d.z());
  if (phi < 0.0) phi += two_pi;
  if (phi >= two_pi) phi = 0.0;
  return {std::acos(std::clamp(d.y(), -1.0, 1.0)), phi};
}

Vector3 direction_of(const LatLong& a) {
  const double s = std::sin(a.theta);
  return {s * std::sin(a.phi), std::cos(a.theta), s * std::cos(a.phi)};
}

Texel texel_of(const LatLong& a, std::size_t width, std::size_t height) {
  return {bin_index(a.phi / two_pi, width), bin_index(a.theta / std::numbers::pi, height)};
}

double texel_solid_angle(std::size_t row, std::size_t width, std::size_t height) {
  const double step = std::numbers::pi / double(height);
  return (std::cos(double(row) * step) - std::cos(double(row + 1) * step)) * two_pi / double(width);
}

LatLong texel_centre(const Texel& t, std::size_t width, std::size_t height) {
  return {(double(t.row) + 0.5) * std::numbers::pi / double(height), (double(t.column) + 0.5) * two_pi / double(width)};
}

}  // namespace pbrfit::render
