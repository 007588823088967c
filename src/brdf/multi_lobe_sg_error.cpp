#include "pbrfit/brdf/multi_lobe_sg_error.hpp"

#include <stdexcept>

#include "pbrfit/brdf/split_sum_dfg.hpp"
#include "pbrfit/integrate/halton.hpp"
#include "pbrfit/integrate/mis_estimator.hpp"

namespace pbrfit::brdf {
namespace {

// One sampling strategy of the estimate: either the GGX target or one SG lobe.
struct LobeStrategy {
  const ltc::GgxTarget* target = nullptr;
  const SphericalGaussian* lobe = nullptr;

  ltc::Vector3 sample(double u1, double u2) const { return lobe ? lobe->sample(u1, u2) : target->sample(u1, u2); }
  double pdf(const ltc::Vector3& w) const { return lobe ? lobe->pdf(w) : target->evaluate(w).pdf; }
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
  const auto squared = [this](const ltc::Vector3& w) {
    const double value = target_.evaluate(w).value;
    return value * value;
  };
  target_squared_norm_ = integrate::integrate_balance_mis(squared, std::span<const LobeStrategy>(&only_target, 1),
                                                          std::span<const std::array<double, 2>>(points_));
}

double MultiLobeSgError::squared_error(const MultiLobeSgParameters& parameters) const {
  const std::vector<SphericalGaussian> lobes = multi_lobe_sg_lobes(parameters, lobe_count_);
  std::vector<LobeStrategy> strategies{{&target_, nullptr}};
  for (const SphericalGaussian& lobe : lobes) strategies.push_back({nullptr, &lobe});
  const auto difference_squared = [&](const ltc::Vector3& w) {
    const double difference = target_.evaluate(w).value - multi_lobe_sg_value(lobes, w);
    return difference * difference;
  };
  return integrate::integrate_balance_mis(difference_squared, std::span<const LobeStrategy>(strategies),
                                          std::span<const std::array<double, 2>>(points_));
}

double MultiLobeSgError::squared_error_normalized(const MultiLobeSgParameters& parameters) const {
  return squared_error(normalized_to(parameters, lobe_count_, target_integral_));
}

}  // namespace pbrfit::brdf
