#include "pbrfit/brdf/multi_lobe_sg_error.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

#include "pbrfit/brdf/split_sum_dfg.hpp"
#include "pbrfit/integrate/compensated_sum.hpp"
#include "pbrfit/integrate/halton.hpp"
#include "pbrfit/integrate/mis_estimator.hpp"

namespace pbrfit::brdf {
namespace {

// One sampling strategy of the estimate: either the GGX target or one SG lobe.
struct LobeStrategy {
  const GgxLobe* target = nullptr;
  const SphericalGaussian* lobe = nullptr;

  Vector3 sample(double u1, double u2) const { return lobe ? lobe->sample(u1, u2) : target->sample(u1, u2); }
  double pdf(const Vector3& w) const { return lobe ? lobe->pdf(w) : target->evaluate(w).pdf; }
};

double albedo(double alpha, double cos_theta_view) {
  integrate::AdaptiveOptions options;
  options.abs_tolerance = 1e-9;
  const DfgEntry entry = integrate_dfg(cos_theta_view, alpha, SmithVisibility::height_correlated, options);
  return entry.scale + entry.bias;
}

}  // namespace

MultiLobeSgError::MultiLobeSgError(double alpha, double cos_theta_view, std::size_t lobe_count,
                                   std::size_t samples_per_strategy)
    : target_(alpha, cos_theta_view), lobe_count_(lobe_count), points_(integrate::halton_points(samples_per_strategy)) {
  if (lobe_count < 2) throw std::invalid_argument("multi-lobe SG error: needs at least 2 lobes");
  if (samples_per_strategy == 0) throw std::invalid_argument("multi-lobe SG error: needs samples");
  target_integral_ = albedo(alpha, cos_theta_view);
  const LobeStrategy only_target{&target_, nullptr};
  const auto squared = [this](const Vector3& w) {
    const double value = target_.evaluate(w).value;
    return value * value;
  };
  target_squared_norm_ = integrate::integrate_balance_mis(squared, std::span<const LobeStrategy>(&only_target, 1),
                                                          std::span<const std::array<double, 2>>(points_));
  for (const auto& u : points_) {
    const Vector3 w = target_.sample(u[0], u[1]);
    const auto t = target_.evaluate(w);
    target_samples_.push_back({w, t.value, t.pdf});
  }
}

// One lobe's constants for evaluating value and density with a single exponential.
struct LobeTerms {
  Vector3 axis;
  double sharpness, amplitude, density_scale;  // value = amplitude e, density = density_scale e
};

// The balance-heuristic MIS estimate of integrate/mis_estimator.hpp with the target's strategy first, its
// samples taken from the cache; terms are summed in the same order.
double MultiLobeSgError::squared_error(const MultiLobeSgParameters& parameters) const {
  const std::vector<SphericalGaussian> lobes = multi_lobe_sg_lobes(parameters, lobe_count_);
  std::vector<LobeTerms> terms;
  for (const SphericalGaussian& lobe : lobes)  // the pdf at the axis is the density's scale (exp(0) = 1)
    terms.push_back({lobe.axis, lobe.sharpness, lobe.amplitude, lobe.pdf(lobe.axis)});
  integrate::CompensatedSum sum;
  const auto add = [&](double target_value, double target_pdf, const Vector3& w) {
    double density = target_pdf, kernel = 0.0;
    for (const LobeTerms& t : terms) {
      const double e = std::exp(-t.sharpness * (1.0 - w.dot(t.axis)));
      kernel += t.amplitude * e;
      density += t.density_scale * e;
    }
    const double difference = target_value - kernel;
    if (density > 0.0) sum.add(difference * difference / density);
  };
  for (const TargetSample& s : target_samples_) add(s.value, s.pdf, s.direction);
  // Each lobe's samples go through the target's vector code together (evaluate_many is evaluate, bit for bit).
  std::vector<Vector3> directions(points_.size());
  std::vector<Lobe::Evaluation> targets(points_.size());
  for (const SphericalGaussian& lobe : lobes) {
    for (std::size_t i = 0; i < points_.size(); ++i) directions[i] = lobe.sample(points_[i][0], points_[i][1]);
    target_.evaluate_many(directions, targets);
    for (std::size_t i = 0; i < points_.size(); ++i) add(targets[i].value, targets[i].pdf, directions[i]);
  }
  return sum.value() / static_cast<double>(points_.size());
}

double MultiLobeSgError::squared_error_normalized(const MultiLobeSgParameters& parameters) const {
  return squared_error(normalized_to(parameters, lobe_count_, target_integral_));
}

}  // namespace pbrfit::brdf
