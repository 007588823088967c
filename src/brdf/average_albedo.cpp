#include <algorithm>
#include <array>
#include <cstddef>

#include "pbrfit/brdf/split_sum_dfg.hpp"

namespace pbrfit::brdf {
namespace {

// Share of the tolerance given to each inner (per-mu) integral. The outer quadrature weights 2 mu
// integrate to 1, so inner errors add at most their maximum to the outer result.
constexpr double inner_tolerance_share = 0.1;

struct InnerTotals {
  std::size_t evaluations = 0;
  double max_error = 0.0;
  bool all_converged = true;
};

}  // namespace

AverageAlbedo integrate_average_albedo(double alpha, SmithVisibility visibility,
                                       const integrate::AdaptiveOptions& options) {
  integrate::AdaptiveOptions inner_options = options;
  inner_options.abs_tolerance = options.abs_tolerance * inner_tolerance_share;
  integrate::AdaptiveOptions outer_options = options;
  outer_options.abs_tolerance = options.abs_tolerance * (1.0 - inner_tolerance_share);

  InnerTotals inner;
  const auto weighted_albedo = [&](const std::array<double, 1>& mu) -> std::array<double, 1> {
    const DfgEntry entry = integrate_dfg(mu[0], alpha, visibility, inner_options);
    inner.evaluations += entry.evaluations;
    inner.max_error = std::max(inner.max_error, entry.error_estimate);
    inner.all_converged = inner.all_converged && entry.converged;
    return {2.0 * mu[0] * (entry.scale + entry.bias)};
  };
  const std::array<integrate::Box<1>, 1> unit_interval = {integrate::Box<1>{{0.0}, {1.0}}};
  const auto outer = integrate::integrate_adaptive<1, 1>(
      weighted_albedo, std::span<const integrate::Box<1>>(unit_interval), outer_options);

  AverageAlbedo albedo;
  albedo.value = outer.value[0];
  albedo.error_estimate = outer.error_estimate + inner.max_error;
  albedo.evaluations = outer.evaluations + inner.evaluations;
  albedo.converged = outer.converged && inner.all_converged && albedo.error_estimate <= options.abs_tolerance;
  return albedo;
}

}  // namespace pbrfit::brdf
