#include "pbrfit/brdf/sheen.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "closed_form_batch.hpp"

namespace pbrfit::brdf {
namespace {

// The coefficients (a, b, c, d, e) of L(x) fitted by Estevez & Kulla at alpha = 0 and at alpha = 1.
constexpr double fit_smooth[5] = {25.3245, 3.32435, 0.16801, -1.27393, -4.85967};
constexpr double fit_rough[5] = {21.5473, 3.82987, 0.19823, -1.97760, -4.32054};

Vector3 half_vector(const Vector3& v, const Vector3& l) { return (v + l).normalized(); }

}  // namespace

double charlie_distribution(double alpha, double n_dot_h) {
  const double sin2 = std::max(0.0, 1.0 - n_dot_h * n_dot_h);
  const double inverse = 1.0 / alpha;
  return (2.0 + inverse) * std::pow(sin2, 0.5 * inverse) / (2.0 * std::numbers::pi);
}

CharlieView::CharlieView(double alpha, const Vector3& v) : alpha_(alpha), v_(v) {
  const double t = (1.0 - alpha) * (1.0 - alpha);
  for (int i = 0; i < 5; ++i) p_[i] = fit_rough[i] + t * (fit_smooth[i] - fit_rough[i]);
  l_half_ = l_of(0.5);
  view_lambda_ = v.z() > 0.0 ? lambda(v.z()) : 0.0;
}

double CharlieView::l_of(double x) const {
  return p_[0] / (1.0 + p_[1] * std::pow(std::max(x, 0.0), p_[2])) + p_[3] * x + p_[4];
}

double CharlieView::lambda(double cosine) const {
  return cosine < 0.5 ? std::exp(l_of(cosine)) : std::exp(2.0 * l_half_ - l_of(1.0 - cosine));
}

double CharlieView::operator()(const Vector3& l) const {
  double value = 0.0;
  many(&l, 1, &value);
  return value;
}

void CharlieView::many(const Vector3* l, std::size_t n, double* out) const {
  if (n == 0) return;
  if (!(v_.z() > 0.0)) {
    std::fill(out, out + n, 0.0);
    return;
  }
  const detail::CharlieConstants constants{
      1.0 / alpha_, v_.x(), v_.y(), v_.z(), view_lambda_, {p_[0], p_[1], p_[2], p_[3], p_[4]}, l_half_};
  detail::charlie_batch(active_kernel_set())(constants, l, n, out);
}

double charlie_lambda(double alpha, double cosine) { return CharlieView(alpha, Vector3::UnitZ()).lambda(cosine); }

double charlie_cosine_weighted(double alpha, const Vector3& v, const Vector3& l) { return CharlieView(alpha, v)(l); }

double ashikhmin_distribution(double alpha, double n_dot_h) {
  const double cos2 = n_dot_h * n_dot_h;
  const double sin2 = std::max(0.0, 1.0 - cos2);
  const double alpha2 = alpha * alpha;
  // exp(-cot^2 / alpha^2) / sin^4 tends to 0 as sin -> 0.
  const double peak = sin2 > 0.0 ? 4.0 * std::exp(-cos2 / (alpha2 * sin2)) / (sin2 * sin2) : 0.0;
  return (1.0 + peak) / (std::numbers::pi * (1.0 + 4.0 * alpha2));
}

double neubelt_visibility(double n_dot_v, double n_dot_l) {
  return 1.0 / (4.0 * (n_dot_l + n_dot_v - n_dot_l * n_dot_v));
}

double ashikhmin_cosine_weighted(double alpha, const Vector3& v, const Vector3& l) {
  if (!(v.z() > 0.0) || !(l.z() > 0.0)) return 0.0;
  return ashikhmin_distribution(alpha, half_vector(v, l).z()) * neubelt_visibility(v.z(), l.z()) * l.z();
}

double fabric_lambert_cosine_weighted(double roughness, const Vector3& v, const Vector3& l) {
  if (!(v.z() > 0.0) || !(l.z() > 0.0)) return 0.0;
  return (1.0 - 0.5 * roughness) * l.z() / std::numbers::pi;
}

}  // namespace pbrfit::brdf
