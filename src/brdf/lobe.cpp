#include "pbrfit/brdf/lobe.hpp"

#include <cmath>
#include <stdexcept>

namespace pbrfit::brdf {

Vector3 view_in_xz_plane(double cos_theta_view) {
  if (!(cos_theta_view > 0.0 && cos_theta_view <= 1.0))
    throw std::invalid_argument("brdf: a lobe needs 0 < cos theta_v <= 1");
  return {std::sqrt(1.0 - cos_theta_view * cos_theta_view), 0.0, cos_theta_view};
}

Lobe::Lobe(double cos_theta_view) : view_(view_in_xz_plane(cos_theta_view)) {}

void Lobe::value_many(std::span<const Vector3> l, std::span<double> out) const {
  for (std::size_t i = 0; i < l.size(); ++i) out[i] = value(l[i]);
}

void Lobe::evaluate_many(std::span<const Vector3> l, std::span<Evaluation> out) const {
  for (std::size_t i = 0; i < l.size(); ++i) out[i] = evaluate(l[i]);
}

}  // namespace pbrfit::brdf
