#include "pbrfit/brdf/disney_diffuse_course_fit.hpp"

#include <algorithm>

namespace pbrfit::brdf {

double course_disney_beta(double roughness, double n_dot_v) {
  return std::max(0.0, -0.2988 + 0.3775 * (1.0 - n_dot_v) + 0.1372 * roughness);
}

double course_disney_zh0(double roughness, double n_dot_v) {
  const double m = std::max(1.0 - n_dot_v, 0.5637);
  return (-0.0913 + 0.3067 * roughness) + (-0.6502 - 1.0803 * roughness) * m + (-0.5993 + 1.0632 * roughness) * m * m;
}

double course_disney_zh1_ratio(double roughness, double n_dot_v) {
  return 1.1635 - 0.0304 * roughness + 0.0162 * (1.0 - n_dot_v);
}

double course_disney_zh2_ratio(double roughness, double n_dot_v) {
  return 0.5725 - 0.0569 * roughness + 0.0386 * (1.0 - n_dot_v);
}

}  // namespace pbrfit::brdf
