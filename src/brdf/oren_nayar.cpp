#include "pbrfit/brdf/oren_nayar.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pbrfit::brdf {

OrenNayarView::OrenNayarView(double sigma, const Vector3& v)
    : v_(v),
      a_(1.0 - 0.5 * sigma * sigma / (sigma * sigma + 0.33)),
      b_(0.45 * sigma * sigma / (sigma * sigma + 0.09)),
      sin_v_(std::sqrt(std::max(0.0, 1.0 - v.z() * v.z()))) {}

double OrenNayarView::operator()(const Vector3& l) const {
  if (!(l.z() > 0.0) || v_.z() < 0.0) return 0.0;
  const double sin_l = std::sqrt(std::max(0.0, 1.0 - l.z() * l.z()));
  double azimuth = 0.0;  // max(0, cos(phi_l - phi_v)) sin(a) tan(b)
  if (sin_l > 0.0 && sin_v_ > 0.0) {
    const double cos_phi = (l.x() * v_.x() + l.y() * v_.y()) / (sin_l * sin_v_);
    // sin(max) tan(min) = sin_l sin_v / cos(min) = sin_l sin_v / max(cos_l, cos_v).
    azimuth = std::max(0.0, cos_phi) * sin_l * sin_v_ / std::max(l.z(), v_.z());
  }
  return (a_ + b_ * azimuth) * l.z() / std::numbers::pi;
}

double oren_nayar_cosine_weighted(double sigma, const Vector3& v, const Vector3& l) { return OrenNayarView(sigma, v)(l); }

}  // namespace pbrfit::brdf
