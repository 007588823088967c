#include "pbrfit/brdf/rusinkiewicz.hpp"

#include <algorithm>
#include <cmath>

namespace pbrfit::brdf {
namespace {


Vector3 rotate_z(const Vector3& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y(), v.z()};
}

Vector3 rotate_y(const Vector3& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x() + s * v.z(), v.y(), -s * v.x() + c * v.z()};
}

Vector3 spherical(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

double polar(const Vector3& v) { return std::acos(std::clamp(v.z(), -1.0, 1.0)); }

}  // namespace

HalfDiff to_half_diff(const Vector3& wi, const Vector3& wo) {
  const Vector3 h = (wi + wo).normalized();
  HalfDiff a;
  a.theta_h = polar(h);
  a.phi_h = std::atan2(h.y(), h.x());
  const Vector3 d = rotate_y(rotate_z(wi, -a.phi_h), -a.theta_h);
  a.theta_d = polar(d);
  a.phi_d = std::atan2(d.y(), d.x());
  return a;
}

DirectionPair from_half_diff(const HalfDiff& a) {
  const Vector3 h = spherical(a.theta_h, a.phi_h);
  const Vector3 wi = rotate_z(rotate_y(spherical(a.theta_d, a.phi_d), a.theta_h), a.phi_h);
  return {wi, 2.0 * wi.dot(h) * h - wi};
}

}  // namespace pbrfit::brdf
