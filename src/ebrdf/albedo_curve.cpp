#include "pbrfit/ebrdf/albedo_curve.hpp"

#include <algorithm>
#include <cmath>

#include "pbrfit/brdf/split_sum_dfg.hpp"

namespace pbrfit::ebrdf {
namespace {

double albedo_cosine_at(std::size_t i, std::size_t points) {
  return min_view_cosine + (1.0 - min_view_cosine) * double(i) / double(points - 1);
}

}  // namespace

AlbedoCurve::AlbedoCurve(const BaseLobe& lobe, std::size_t points) {
  if (lobe.component == Component::diffuse) return;
  integrate::AdaptiveOptions options;
  options.abs_tolerance = 1e-6;
  options.max_evaluations = 2'000'000;
  values_.resize(std::max<std::size_t>(points, 2));
  for (std::size_t i = 0; i < values_.size(); ++i) {
    const auto entry = brdf::integrate_dfg(albedo_cosine_at(i, values_.size()), lobe.alpha,
                                           brdf::SmithVisibility::height_correlated, options);
    values_[i] = std::clamp(entry.scale + entry.bias, 0.0, 1.0);
  }
}

double AlbedoCurve::at(double cos_theta) const {
  if (values_.empty()) return 1.0;
  const double c = std::clamp(cos_theta, min_view_cosine, 1.0);
  const double position = (c - min_view_cosine) / (1.0 - min_view_cosine) * double(values_.size() - 1);
  const std::size_t i = std::min(values_.size() - 2, static_cast<std::size_t>(position));
  const double t = position - double(i);
  return values_[i] * (1.0 - t) + values_[i + 1] * t;
}

}  // namespace pbrfit::ebrdf
