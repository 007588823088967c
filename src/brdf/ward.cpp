#include "pbrfit/brdf/ward.hpp"

#include <cmath>

#include "pbrfit/brdf/beckmann.hpp"

namespace pbrfit::brdf {

double ward_cosine_weighted(double alpha, const Vector3& v, const Vector3& l) {
  if (!(v.z() > 0.0) || !(l.z() > 0.0)) return 0.0;
  // (l.h)^2 = (1 + l.v) / 2 for h = normalize(v + l).
  const double l_dot_h_squared = 0.5 * (1.0 + l.dot(v));
  if (!(l_dot_h_squared > 0.0)) return 0.0;
  const Vector3 h = (v + l).normalized();
  return beckmann_distribution(alpha, h.z()) / (4.0 * l_dot_h_squared) * l.z();
}

}  // namespace pbrfit::brdf
