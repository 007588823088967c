#include "pbrfit/brdf/cook_torrance.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pbrfit::brdf {

double cook_torrance_geometry(double n_dot_h, double n_dot_v, double n_dot_l, double v_dot_h) {
  if (!(v_dot_h > 0.0)) return 0.0;
  return std::min({1.0, 2.0 * n_dot_h * n_dot_v / v_dot_h, 2.0 * n_dot_h * n_dot_l / v_dot_h});
}

double cook_torrance_cosine_weighted(double m, const Vector3& v, const Vector3& l) {
  if (!(v.z() > 0.0) || !(l.z() > 0.0)) return 0.0;
  const Vector3 sum = v + l;
  const double length = sum.norm();
  if (length == 0.0) return 0.0;
  const Vector3 h = sum / length;
  const double cos2 = h.z() * h.z();
  const double m2 = m * m;
  const double distribution = std::exp(-(1.0 - cos2) / (cos2 * m2)) / (m2 * cos2 * cos2);
  return distribution * cook_torrance_geometry(h.z(), v.z(), l.z(), v.dot(h)) / (std::numbers::pi * v.z());
}

}  // namespace pbrfit::brdf
