#include "pbrfit/brdf/sampled_lobe.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "pbrfit/brdf/ggx.hpp"
#include "pbrfit/brdf/ggx_lobe.hpp"

namespace pbrfit::brdf {

double cosine_hemisphere_pdf(const Vector3& l) { return l.z() > 0.0 ? l.z() / std::numbers::pi : 0.0; }

Vector3 sample_cosine_hemisphere(double u1, double u2) {
  const double radius = std::sqrt(u1);
  const double phi = 2.0 * std::numbers::pi * u2;
  return {radius * std::cos(phi), radius * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - u1))};
}

double uniform_hemisphere_pdf(const Vector3& l) { return l.z() > 0.0 ? 0.5 / std::numbers::pi : 0.0; }

Vector3 sample_uniform_hemisphere(double u1, double u2) {
  const double z = 1.0 - u1;
  const double radius = std::sqrt(std::max(0.0, 1.0 - z * z));
  const double phi = 2.0 * std::numbers::pi * u2;
  return {radius * std::cos(phi), radius * std::sin(phi), z};
}

DirectionSampler::DirectionSampler(DirectionSampling sampling, double alpha, const Vector3& view)
    : sampling_(sampling), alpha_(alpha), view_(view) {
  if (sampling == DirectionSampling::ggx_visible) {
    if (!(alpha > 0.0) || !std::isfinite(alpha))
      throw std::invalid_argument("brdf: GGX visible-normal sampling needs alpha > 0");
    view_masking_ = 1.0 / (1.0 + ggx_smith_lambda(alpha, view.z()));
  }
}

double DirectionSampler::pdf(const Vector3& l) const {
  switch (sampling_) {
    case DirectionSampling::cosine:
      return cosine_hemisphere_pdf(l);
    case DirectionSampling::uniform:
      return uniform_hemisphere_pdf(l);
    case DirectionSampling::ggx_visible: {
      const Vector3 sum = view_ + l;
      const double length = sum.norm();
      if (length == 0.0) return 0.0;
      return view_masking_ * ggx_distribution(alpha_, sum.z() / length) / (4.0 * view_.z());
    }
  }
  return 0.0;
}

Vector3 DirectionSampler::sample(double u1, double u2) const {
  switch (sampling_) {
    case DirectionSampling::cosine:
      return sample_cosine_hemisphere(u1, u2);
    case DirectionSampling::uniform:
      return sample_uniform_hemisphere(u1, u2);
    case DirectionSampling::ggx_visible:
      return sample_ggx_visible_reflection(alpha_, view_, u1, u2);
  }
  return Vector3::UnitZ();
}

}  // namespace pbrfit::brdf
