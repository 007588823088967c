#include "pbrfit/brdf/disney_diffuse.hpp"

#include <numbers>

namespace pbrfit::brdf {

double disney_retro_factor(double f_d90, double cosine) {
  const double m = 1.0 - cosine;
  const double m2 = m * m;
  return 1.0 + (f_d90 - 1.0) * m2 * m2 * m;
}

double disney_diffuse_cbrdf(double roughness, const Vector3& v, const Vector3& l) {
  const double n_dot_l = l.z();
  if (!(n_dot_l > 0.0) || v.z() < 0.0) return 0.0;
  // (l.h)^2 = (1 + l.v) / 2 for h = normalize(v + l).
  const double l_dot_h_squared = 0.5 * (1.0 + l.dot(v));
  const double f_d90 = 0.5 + 2.0 * roughness * l_dot_h_squared;
  return disney_retro_factor(f_d90, n_dot_l) * disney_retro_factor(f_d90, v.z()) * n_dot_l / std::numbers::pi;
}

}  // namespace pbrfit::brdf
