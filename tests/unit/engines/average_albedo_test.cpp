#include <catch2/catch_test_macros.hpp>

#include <array>
#include <cmath>

#include "dfg_monte_carlo.hpp"
#include "pbrfit/brdf/split_sum_dfg.hpp"

using namespace pbrfit::brdf;
using pbrfit::integrate::AdaptiveOptions;

TEST_CASE("Average albedo of the mirror is 1") {
  const AverageAlbedo mirror = integrate_average_albedo(0.0, SmithVisibility::height_correlated, AdaptiveOptions{});
  CHECK(mirror.converged);
  CHECK(std::abs(mirror.value - 1.0) < 1e-12);
}

TEST_CASE("Average albedo converges, decreases with roughness and matches Monte Carlo") {
  std::uint64_t item = 0;
  for (SmithVisibility visibility : all_smith_visibilities) {
    double previous = 1.0;
    for (double alpha : {0.1, 0.5, 1.0}) {
      const AverageAlbedo albedo = integrate_average_albedo(alpha, visibility, AdaptiveOptions{});
      const auto mc = pbrfit::test::monte_carlo_average_albedo(alpha, visibility, 1'000'000, item++);
      CAPTURE(static_cast<int>(visibility), alpha, albedo.value, albedo.error_estimate, mc.mean, mc.standard_error);
      CHECK(albedo.converged);
      CHECK(albedo.error_estimate <= 1e-6);
      CHECK(albedo.evaluations > 15);  // the inner integrals are counted
      CHECK(albedo.value < previous);
      CHECK(mc.standard_error < 2.5e-3);
      CHECK(std::abs(albedo.value - mc.mean) < 4.0 * mc.standard_error);
      previous = albedo.value;
    }
  }
}
