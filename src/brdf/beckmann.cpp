#include "pbrfit/brdf/beckmann.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "closed_form_batch.hpp"

namespace pbrfit::brdf {

double beckmann_distribution(double alpha, double n_dot_h) {
  if (!(n_dot_h > 0.0)) return 0.0;
  const double cos2 = n_dot_h * n_dot_h;
  const double tan2 = (1.0 - cos2) / cos2;
  const double alpha2 = alpha * alpha;
  return std::exp(-tan2 / alpha2) / (std::numbers::pi * alpha2 * cos2 * cos2);
}

double beckmann_smith_lambda(double alpha, double n_dot_w) {
  if (!(n_dot_w > 0.0)) return std::numeric_limits<double>::infinity();
  if (n_dot_w >= 1.0) return 0.0;
  const double a = n_dot_w / (alpha * std::sqrt(1.0 - n_dot_w * n_dot_w));
  if (a > 26.0) return 0.0;  // erfc(a) and exp(-a^2) underflow to 0 long before
  // (erf(a) - 1) / 2 = -erfc(a) / 2, without cancellation for large a.
  return 0.5 * (std::exp(-a * a) / (a * std::sqrt(std::numbers::pi)) - std::erfc(a));
}

BeckmannView::BeckmannView(double alpha, const Vector3& v)
    : alpha_(alpha), v_(v), view_lambda_(v.z() > 0.0 ? beckmann_smith_lambda(alpha, v.z()) : 0.0) {}

double BeckmannView::operator()(const Vector3& l) const {
  double value = 0.0;
  many(&l, 1, &value);
  return value;
}

void BeckmannView::many(const Vector3* l, std::size_t n, double* out) const {
  if (n == 0) return;
  if (!(v_.z() > 0.0)) {
    std::fill(out, out + n, 0.0);
    return;
  }
  const detail::BeckmannConstants constants{alpha_, v_.x(), v_.y(), v_.z(), view_lambda_};
  detail::beckmann_batch(active_kernel_set())(constants, l, n, out);
}

double beckmann_cosine_weighted(double alpha, const Vector3& v, const Vector3& l) { return BeckmannView(alpha, v)(l); }

}  // namespace pbrfit::brdf
