#include "pbrfit/brdf/split_sum_dfg.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

#include "dfg_integrand.hpp"

namespace pbrfit::brdf {
namespace {

// Two initial tiles split at phi = pi/2: at mu = 0 the horizon CDF jumps there.
constexpr std::array<integrate::Box<2>, 2> dfg_initial_tiles = {
    integrate::Box<2>{{0.0, 0.0}, {0.5, 1.0}},
    integrate::Box<2>{{0.5, 0.0}, {1.0, 1.0}},
};

// alpha = 0: h = n, G = 1, l is the mirror direction and n.l = n.v, so the lobe integrates to 1.
DfgEntry mirror_entry(double n_dot_v) {
  const double fresnel = pow5(1.0 - n_dot_v);
  DfgEntry entry;
  entry.scale = 1.0 - fresnel;
  entry.bias = fresnel;
  entry.converged = true;
  return entry;
}

template <SmithVisibility Convention>
DfgEntry integrate_rough(double n_dot_v, double alpha, const integrate::AdaptiveOptions& options) {
  const DfgIntegrand<Convention> integrand(n_dot_v, alpha);
  const auto result = integrate::integrate_adaptive<2, 2>(
      integrand, std::span<const integrate::Box<2>>(dfg_initial_tiles), options);
  DfgEntry entry;
  entry.scale = result.value[0];
  entry.bias = result.value[1];
  entry.error_estimate = result.error_estimate;
  entry.evaluations = result.evaluations;
  entry.converged = result.converged;
  return entry;
}

}  // namespace

DfgEntry integrate_dfg(double n_dot_v, double alpha, SmithVisibility visibility,
                       const integrate::AdaptiveOptions& options) {
  if (!(n_dot_v >= 0.0 && n_dot_v <= 1.0)) throw std::invalid_argument("integrate_dfg: n_dot_v outside [0, 1]");
  if (!(alpha >= 0.0 && std::isfinite(alpha))) throw std::invalid_argument("integrate_dfg: alpha must be >= 0");
  if (alpha == 0.0) return mirror_entry(n_dot_v);
  switch (visibility) {
    case SmithVisibility::separable:
      return integrate_rough<SmithVisibility::separable>(n_dot_v, alpha, options);
    case SmithVisibility::separable_schlick:
      return integrate_rough<SmithVisibility::separable_schlick>(n_dot_v, alpha, options);
    case SmithVisibility::height_correlated:
      return integrate_rough<SmithVisibility::height_correlated>(n_dot_v, alpha, options);
  }
  throw std::invalid_argument("integrate_dfg: unknown visibility convention");
}

}  // namespace pbrfit::brdf
