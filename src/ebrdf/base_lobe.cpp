#include "pbrfit/ebrdf/base_lobe.hpp"

#include <algorithm>
#include <cmath>

#include "pbrfit/ltc/clamped_cosine.hpp"

namespace pbrfit::ebrdf {

Frame texel_frame(const Vector3& n, const Vector3& v) {
  Vector3 tangent = v - v.dot(n) * n;
  if (tangent.norm() < 1e-9) return Frame::from_z(n);
  tangent.normalize();
  return {tangent, n.cross(tangent), n};
}

BaseLobeLtc::BaseLobeLtc(const BaseLobe& lobe) : lobe_(lobe) {
  if (lobe.component == Component::specular) curve_.emplace(lobe.alpha);
}

LtcLookup BaseLobeLtc::at(const Vector3& n, const Vector3& v) const {
  if (!curve_) return {Matrix3::Identity(), 1.0};
  return curve_->at(std::max(v.dot(n), min_view_cosine));
}

Vector3 sample_base_lobe(const LtcLookup& ltc, const Frame& frame, const std::array<double, 2>& u) {
  return frame.from_local((ltc.matrix * ltc::sample_clamped_cosine(u[0], u[1])).normalized()).normalized();
}

std::array<double, 2> stratified_point(std::size_t k, std::size_t n, const std::array<double, 2>& shift) {
  constexpr double inverse_golden_ratio = 0.6180339887498949;
  const auto wrap = [](double x) { return x - std::floor(x); };
  return {wrap((double(k) + 0.5) / double(n) + shift[0]), wrap(double(k) * inverse_golden_ratio + shift[1])};
}

}  // namespace pbrfit::ebrdf
