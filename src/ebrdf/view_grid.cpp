#include "pbrfit/ebrdf/view_grid.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pbrfit::ebrdf {

namespace {

constexpr double top_elevation = 0.999 * std::numbers::pi / 2.0;

}  // namespace

double ViewGrid::theta(std::size_t i) const {
  if (n_theta == 1) return 0.1;
  return top_elevation * std::sin(double(i) / double(n_theta - 1) * std::numbers::pi / 2.0);
}

double ViewGrid::theta_position(double theta) const {
  if (n_theta == 1) return 0.0;
  const double x = std::asin(std::clamp(theta / top_elevation, 0.0, 1.0)) * 2.0 / std::numbers::pi;
  return x * double(n_theta - 1);
}

double ViewGrid::phi(std::size_t j) const { return 2.0 * std::numbers::pi * double(j) / double(n_phi); }

Vector3 ViewGrid::direction(std::size_t view) const {
  const double t = theta(view / n_phi), p = phi(view % n_phi);
  return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

Vector3 rotate_azimuth_to_zero(const Vector3& w, double phi) {
  const double c = std::cos(phi), s = std::sin(phi);
  return {c * w.x() + s * w.y(), -s * w.x() + c * w.y(), w.z()};
}

}  // namespace pbrfit::ebrdf
