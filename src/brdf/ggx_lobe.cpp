#include "pbrfit/brdf/ggx_lobe.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "ggx_lobe_batch.hpp"
#include "pbrfit/brdf/ggx.hpp"

namespace pbrfit::brdf {

double ggx_cosine_weighted(double alpha, const Vector3& v, const Vector3& l) {
  if (!(v.z() > 0.0) || !(l.z() > 0.0)) return 0.0;
  const Vector3 sum = v + l;
  const double length = sum.norm();
  if (length == 0.0) return 0.0;
  const double distribution = ggx_distribution(alpha, sum.z() / length);
  const double masking = smith_masking_shadowing(SmithVisibility::height_correlated, alpha, v.z(), l.z());
  return distribution * masking / (4.0 * v.z());
}

Vector3 mirror_about_normal(const Vector3& w) { return {-w.x(), -w.y(), w.z()}; }

namespace {

double checked_alpha(double alpha) {
  if (!(alpha > 0.0) || !std::isfinite(alpha)) throw std::invalid_argument("brdf: the GGX lobe needs alpha > 0");
  return alpha;
}

}  // namespace

GgxLobe::GgxLobe(double alpha, double cos_theta_view) : Lobe(cos_theta_view), alpha_(checked_alpha(alpha)) {
  view_lambda_ = ggx_smith_lambda(alpha, cos_theta_view);
  masking_ = 1.0 / (1.0 + view_lambda_);
}

GgxLobe::Evaluation GgxLobe::evaluate(const Vector3& l) const {
  const Vector3 sum = view() + l;
  const double length = sum.norm();
  if (length == 0.0) return {};
  const double distribution = ggx_distribution(alpha_, sum.z() / length);
  const double scale = distribution / (4.0 * view().z());
  Evaluation result;
  result.pdf = masking_ * scale;
  if (l.z() > 0.0) result.value = scale / (1.0 + view_lambda_ + ggx_smith_lambda(alpha_, l.z()));
  return result;
}

void GgxLobe::evaluate_many(std::span<const Vector3> l, std::span<Evaluation> out) const {
  if (l.empty()) return;
  const detail::GgxLobeConstants constants{alpha_, view().x(), view().y(), view().z(), view_lambda_, masking_};
  detail::ggx_lobe_batch(active_kernel_set())(constants, l.data(), l.size(), out.data());
}

void GgxLobe::value_many(std::span<const Vector3> l, std::span<double> out) const {
  std::array<Evaluation, 64> group;
  for (std::size_t first = 0; first < l.size(); first += group.size()) {
    const std::size_t n = std::min(group.size(), l.size() - first);
    evaluate_many(l.subspan(first, n), std::span(group.data(), n));
    for (std::size_t i = 0; i < n; ++i) out[first + i] = group[i].value;
  }
}

Vector3 GgxLobe::sample(double u1, double u2) const { return sample_ggx_visible_reflection(alpha_, view(), u1, u2); }

// Heitz 2018: a visible normal of the stretched (alpha = 1) configuration, sampled on the projected disk
// and warped onto the half disk the view sees, then unstretched and used as the mirror about v.
Vector3 sample_ggx_visible_reflection(double alpha, const Vector3& v, double u1, double u2) {
  const Vector3 stretched_view = Vector3(alpha * v.x(), alpha * v.y(), v.z()).normalized();
  const double tangent_length = std::hypot(stretched_view.x(), stretched_view.y());
  const Vector3 t1 = tangent_length > 0.0
                         ? Vector3(-stretched_view.y() / tangent_length, stretched_view.x() / tangent_length, 0.0)
                         : Vector3::UnitX();
  const Vector3 t2 = stretched_view.cross(t1);
  const double radius = std::sqrt(u1);
  const double phi = 2.0 * std::numbers::pi * u2;
  const double p1 = radius * std::cos(phi);
  const double blend = 0.5 * (1.0 + stretched_view.z());
  const double p2 = (1.0 - blend) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + blend * radius * std::sin(phi);
  const Vector3 stretched_normal =
      p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2)) * stretched_view;
  const Vector3 normal =
      Vector3(alpha * stretched_normal.x(), alpha * stretched_normal.y(), std::max(0.0, stretched_normal.z()))
          .normalized();
  return (2.0 * v.dot(normal) * normal - v).normalized();
}

}  // namespace pbrfit::brdf
