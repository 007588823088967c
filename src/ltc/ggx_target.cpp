#include "pbrfit/ltc/ggx_target.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "pbrfit/brdf/ggx.hpp"

namespace pbrfit::ltc {

GgxTarget::GgxTarget(double alpha, double cos_theta_view) : alpha_(alpha) {
  if (!(alpha > 0.0) || !std::isfinite(alpha)) throw std::invalid_argument("ltc: the GGX target needs alpha > 0");
  if (!(cos_theta_view > 0.0 && cos_theta_view <= 1.0)) {
    throw std::invalid_argument("ltc: the GGX target needs 0 < cos theta_v <= 1");
  }
  view_ = Vector3(std::sqrt(1.0 - cos_theta_view * cos_theta_view), 0.0, cos_theta_view);
  view_lambda_ = brdf::ggx_smith_lambda(alpha, cos_theta_view);
  masking_ = 1.0 / (1.0 + view_lambda_);
}

GgxTarget::Evaluation GgxTarget::evaluate(const Vector3& l) const {
  const Vector3 sum = view_ + l;
  const double length = sum.norm();
  if (length == 0.0) return {};
  const double distribution = brdf::ggx_distribution(alpha_, sum.z() / length);
  const double scale = distribution / (4.0 * view_.z());
  Evaluation result;
  result.pdf = masking_ * scale;
  if (l.z() > 0.0) result.value = scale / (1.0 + view_lambda_ + brdf::ggx_smith_lambda(alpha_, l.z()));
  return result;
}

// Heitz 2018: a visible normal of the stretched (alpha = 1) configuration, sampled on the projected disk
// and warped onto the half disk the view sees, then unstretched and used as the mirror about v.
Vector3 GgxTarget::sample(double u1, double u2) const {
  const Vector3 stretched_view = Vector3(alpha_ * view_.x(), alpha_ * view_.y(), view_.z()).normalized();
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
      Vector3(alpha_ * stretched_normal.x(), alpha_ * stretched_normal.y(), std::max(0.0, stretched_normal.z()))
          .normalized();
  return (2.0 * view_.dot(normal) * normal - view_).normalized();
}

}  // namespace pbrfit::ltc
