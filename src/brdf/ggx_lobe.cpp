#include "pbrfit/brdf/ggx_lobe.hpp"

#include "pbrfit/brdf/ggx.hpp"

namespace pbrfit::brdf {

double ggx_cosine_weighted(double alpha, const ltc::Vector3& v, const ltc::Vector3& l) {
  if (!(v.z() > 0.0) || !(l.z() > 0.0)) return 0.0;
  const ltc::Vector3 sum = v + l;
  const double length = sum.norm();
  if (length == 0.0) return 0.0;
  const double distribution = ggx_distribution(alpha, sum.z() / length);
  const double masking = smith_masking_shadowing(SmithVisibility::height_correlated, alpha, v.z(), l.z());
  return distribution * masking / (4.0 * v.z());
}

ltc::Vector3 mirror_about_normal(const ltc::Vector3& w) { return {-w.x(), -w.y(), w.z()}; }

}  // namespace pbrfit::brdf
