#include <catch2/catch_test_macros.hpp>

#include <array>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "dfg_monte_carlo.hpp"
#include "kernel_set_scope.hpp"
#include "pbrfit/core/kernel_set.hpp"
#include "pbrfit/brdf/split_sum_dfg.hpp"

using namespace pbrfit::brdf;
using pbrfit::integrate::AdaptiveOptions;
using pbrfit::test::LightSampling;

namespace {

constexpr double tolerance = 1e-6;

DfgEntry entry(double n_dot_v, double alpha, SmithVisibility visibility) {
  AdaptiveOptions options;
  options.abs_tolerance = tolerance;
  return integrate_dfg(n_dot_v, alpha, visibility, options);
}

void check_against_monte_carlo(double n_dot_v, double alpha, SmithVisibility visibility, LightSampling sampling,
                               std::uint64_t item) {
  const DfgEntry quadrature = entry(n_dot_v, alpha, visibility);
  const auto mc = pbrfit::test::monte_carlo_dfg(n_dot_v, alpha, visibility, sampling, 1'000'000, item);
  CAPTURE(n_dot_v, alpha, static_cast<int>(visibility), static_cast<int>(sampling));
  CAPTURE(quadrature.scale, mc.scale.mean, mc.scale.standard_error);
  CAPTURE(quadrature.bias, mc.bias.mean, mc.bias.standard_error);
  REQUIRE(quadrature.converged);
  // Weights are bounded, so 10^6 samples pin each term to ~0.3% or better (worst at grazing views).
  CHECK(mc.scale.standard_error < 2.5e-3);
  CHECK(mc.bias.standard_error < 2.5e-3);
  CHECK(std::abs(quadrature.scale - mc.scale.mean) < 4.0 * mc.scale.standard_error);
  CHECK(std::abs(quadrature.bias - mc.bias.mean) < 4.0 * mc.bias.standard_error + 1e-6);
}

}  // namespace

TEST_CASE("alpha = 0 is the mirror limit in closed form") {
  for (SmithVisibility visibility : all_smith_visibilities) {
    for (double mu : {0.0, 0.3, 1.0}) {
      const DfgEntry mirror = entry(mu, 0.0, visibility);
      const double fresnel = std::pow(1.0 - mu, 5.0);
      CHECK(mirror.converged);
      CHECK(mirror.evaluations == 0);
      CHECK(std::abs(mirror.bias - fresnel) < 1e-15);
      CHECK(std::abs(mirror.scale - (1.0 - fresnel)) < 1e-15);
    }
  }
}

TEST_CASE("Split-sum terms converge and conserve energy: scale + bias <= 1") {
  for (SmithVisibility visibility : all_smith_visibilities) {
    for (double mu : {0.0, 0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 1.0}) {
      for (double alpha : {1e-3, 0.01, 0.1, 0.3, 0.6, 1.0}) {
        const DfgEntry e = entry(mu, alpha, visibility);
        CAPTURE(static_cast<int>(visibility), mu, alpha, e.scale, e.bias, e.error_estimate);
        CHECK(e.converged);
        CHECK(e.error_estimate <= tolerance);
        CHECK(e.scale >= 0.0);
        CHECK(e.bias >= 0.0);
        CHECK(e.scale + e.bias <= 1.0 + 1e-6);
      }
    }
  }
}

TEST_CASE("scale + bias tends to 1 as the roughness vanishes") {
  for (SmithVisibility visibility : all_smith_visibilities) {
    for (double mu : {0.1, 0.4, 0.8, 1.0}) {
      const DfgEntry e = entry(mu, 1e-4, visibility);
      CAPTURE(static_cast<int>(visibility), mu, e.scale, e.bias);
      CHECK(std::abs(e.scale + e.bias - 1.0) < 1e-3);
      CHECK(std::abs(e.bias - std::pow(1.0 - mu, 5.0)) < 1e-3);
    }
  }
}

TEST_CASE("The grazing view mu = 0 is the finite limit of mu -> 0") {
  for (SmithVisibility visibility : all_smith_visibilities) {
    for (double alpha : {0.05, 0.5, 1.0}) {
      const DfgEntry at_zero = entry(0.0, alpha, visibility);
      const DfgEntry near_zero = entry(1e-7, alpha, visibility);
      CAPTURE(static_cast<int>(visibility), alpha, at_zero.scale, near_zero.scale, at_zero.bias, near_zero.bias);
      CHECK(at_zero.converged);
      CHECK(std::isfinite(at_zero.scale));
      CHECK(std::abs(at_zero.scale - near_zero.scale) < 1e-5);
      CHECK(std::abs(at_zero.bias - near_zero.bias) < 1e-5);
    }
  }
}

TEST_CASE("Split-sum terms agree with independent Monte Carlo estimates") {
  struct Cell {
    double n_dot_v;
    double alpha;
  };
  // Half-vector sampling (h ~ D(h)(n.h) over the full azimuth circle) at cells spread over mu and alpha.
  constexpr std::array<Cell, 5> cells = {{{0.05, 0.3}, {0.25, 0.02}, {0.5, 0.6}, {0.8, 0.1}, {0.97, 1.0}}};
  std::uint64_t item = 0;
  for (SmithVisibility visibility : all_smith_visibilities) {
    for (const Cell& cell : cells) {
      check_against_monte_carlo(cell.n_dot_v, cell.alpha, visibility, LightSampling::ggx_half_vector, item++);
    }
  }
  // Uniform light sampling (no microfacet importance at all) on rough cells, including the grazing view.
  constexpr std::array<Cell, 2> rough_cells = {{{0.0, 0.5}, {0.35, 0.8}}};
  for (SmithVisibility visibility : all_smith_visibilities) {
    for (const Cell& cell : rough_cells) {
      check_against_monte_carlo(cell.n_dot_v, cell.alpha, visibility, LightSampling::uniform_hemisphere, item++);
    }
  }
}

TEST_CASE("Split-sum entries are bitwise reproducible") {
  const DfgEntry first = entry(0.37, 0.21, SmithVisibility::height_correlated);
  const DfgEntry second = entry(0.37, 0.21, SmithVisibility::height_correlated);
  CHECK(std::memcmp(&first.scale, &second.scale, sizeof(double)) == 0);
  CHECK(std::memcmp(&first.bias, &second.bias, sizeof(double)) == 0);
  CHECK(first.evaluations == second.evaluations);
}

// The integrand runs as vector code over each Gauss-Kronrod line (brdf/dfg_line.hpp): between kernel sets
// only its exp may round differently, which moves an entry by far less than the tolerance.
TEST_CASE("Split-sum entries agree across kernel sets to rounding") {
  constexpr std::array<std::array<double, 2>, 5> cases{{{0.37, 0.21}, {1.0, 0.05}, {0.02, 0.9}, {0.0, 0.3}, {0.6, 1e-3}}};
  for (const SmithVisibility visibility : all_smith_visibilities) {
    for (const auto& [n_dot_v, alpha] : cases) {
      DfgEntry generic;
      {
        const kernel_test::KernelSetScope scope(pbrfit::KernelSet::generic);
        generic = entry(n_dot_v, alpha, visibility);
      }
      for (const pbrfit::KernelSet set : pbrfit::kernel_sets_available()) {
        const kernel_test::KernelSetScope scope(set);
        const DfgEntry other = entry(n_dot_v, alpha, visibility);
        CAPTURE(pbrfit::kernel_set_name(set), n_dot_v, alpha, static_cast<int>(visibility));
        REQUIRE(other.converged);
        CHECK(std::abs(other.scale - generic.scale) <= 1e-13);
        CHECK(std::abs(other.bias - generic.bias) <= 1e-13);
        CHECK(other.evaluations == generic.evaluations);
      }
    }
  }
}

TEST_CASE("Split-sum inputs outside the domain are rejected") {
  CHECK_THROWS_AS(entry(-0.1, 0.5, SmithVisibility::separable), std::invalid_argument);
  CHECK_THROWS_AS(entry(1.5, 0.5, SmithVisibility::separable), std::invalid_argument);
  CHECK_THROWS_AS(entry(0.5, -0.5, SmithVisibility::separable), std::invalid_argument);
  CHECK_THROWS_AS(entry(std::nan(""), 0.5, SmithVisibility::separable), std::invalid_argument);
}
