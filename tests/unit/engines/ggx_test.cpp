#include <catch2/catch_test_macros.hpp>

#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "pbrfit/brdf/ggx.hpp"
#include "pbrfit/brdf/roughness.hpp"
#include "pbrfit/integrate/adaptive_cubature.hpp"

using namespace pbrfit::brdf;
using pbrfit::integrate::AdaptiveOptions;
using pbrfit::integrate::Box;

TEST_CASE("GGX D matches its closed form") {
  CHECK(std::abs(ggx_distribution(1.0, 0.3) - 1.0 / std::numbers::pi) < 1e-15);  // alpha = 1 is uniform
  const double alpha = 0.2;
  CHECK(std::abs(ggx_distribution(alpha, 1.0) - 1.0 / (std::numbers::pi * alpha * alpha)) < 1e-12);
  CHECK(ggx_distribution(alpha, 0.0) > 0.0);
  CHECK(ggx_distribution(alpha, -0.1) == 0.0);
}

TEST_CASE("GGX D is normalized: integral of D(h) (n.h) over the hemisphere is 1") {
  // Plain (cos theta, phi) coordinates, dw = dcos dphi: the peak at cos = 1 must be found by refinement.
  for (double alpha : {0.05, 0.1, 0.3, 0.6, 1.0}) {
    const auto projected_d = [alpha](const std::array<double, 2>& x) {
      return std::array<double, 1>{ggx_distribution(alpha, x[0]) * x[0]};
    };
    const Box<2> hemisphere{{0.0, 0.0}, {1.0, 2.0 * std::numbers::pi}};
    AdaptiveOptions options;
    options.abs_tolerance = 1e-8;
    const auto result =
        pbrfit::integrate::integrate_adaptive<2, 1>(projected_d, std::span<const Box<2>>(&hemisphere, 1), options);
    CAPTURE(alpha, result.value[0], result.tiles);
    CHECK(result.converged);
    CHECK(std::abs(result.value[0] - 1.0) < 1e-6);
  }
}

TEST_CASE("Smith Lambda and G1 agree with the tan-theta definitions") {
  for (double alpha : {0.01, 0.3, 1.0, 1.7}) {
    for (double cosine : {0.01, 0.2, 0.5, 0.9, 1.0}) {
      const double tan_squared = (1.0 - cosine * cosine) / (cosine * cosine);
      const double lambda = (-1.0 + std::sqrt(1.0 + alpha * alpha * tan_squared)) / 2.0;
      CAPTURE(alpha, cosine);
      CHECK(std::abs(ggx_smith_lambda(alpha, cosine) - lambda) <= 1e-14 * (1.0 + lambda));
      const double g1 = 1.0 / (1.0 + lambda);
      CHECK(std::abs(smith_masking_shadowing(SmithVisibility::separable, alpha, cosine, 1.0) - g1) < 1e-14);
      const double k = alpha / 2.0;
      const double schlick = cosine / (cosine * (1.0 - k) + k);
      CHECK(std::abs(smith_masking_shadowing(SmithVisibility::separable_schlick, alpha, cosine, 1.0) - schlick) <
            1e-14);
    }
  }
  CHECK(ggx_smith_lambda(0.0, 0.3) == 0.0);
  CHECK(std::isinf(ggx_smith_lambda(0.5, 0.0)));
}

TEST_CASE("Masking-shadowing conventions") {
  for (double alpha : {0.05, 0.5, 1.0}) {
    for (double n_dot_v : {0.05, 0.5, 1.0}) {
      for (double n_dot_l : {0.05, 0.3, 0.9}) {
        CAPTURE(alpha, n_dot_v, n_dot_l);
        const double separable = smith_masking_shadowing(SmithVisibility::separable, alpha, n_dot_v, n_dot_l);
        const double correlated =
            smith_masking_shadowing(SmithVisibility::height_correlated, alpha, n_dot_v, n_dot_l);
        const double lambda_v = ggx_smith_lambda(alpha, n_dot_v);
        const double lambda_l = ggx_smith_lambda(alpha, n_dot_l);
        CHECK(std::abs(correlated - 1.0 / (1.0 + lambda_v + lambda_l)) < 1e-14);
        CHECK(correlated >= separable * (1.0 - 1e-15));  // 1 / (1 + a + b) >= 1 / ((1 + a)(1 + b))
        CHECK(correlated <= 1.0);
      }
    }
  }
  for (SmithVisibility visibility : all_smith_visibilities) {
    CHECK(smith_masking_shadowing(visibility, 0.4, 0.0, 0.5) == 0.0);
    CHECK(smith_masking_shadowing(visibility, 0.4, 0.5, -0.1) == 0.0);
    CHECK(smith_masking_shadowing(visibility, 0.0, 0.3, 0.5) == 1.0);  // mirror limit
  }
}

TEST_CASE("Visibility equals G / (4 n.v n.l) and stays finite at grazing angles") {
  for (SmithVisibility visibility : all_smith_visibilities) {
    for (double alpha : {0.01, 0.3, 1.0}) {
      for (double n_dot_v : {1e-3, 0.2, 0.7, 1.0}) {
        for (double n_dot_l : {1e-3, 0.4, 1.0}) {
          CAPTURE(static_cast<int>(visibility), alpha, n_dot_v, n_dot_l);
          const double g = smith_masking_shadowing(visibility, alpha, n_dot_v, n_dot_l);
          const double v = smith_visibility(visibility, alpha, n_dot_v, n_dot_l);
          CHECK(std::abs(v - g / (4.0 * n_dot_v * n_dot_l)) <= 1e-12 * v);
        }
      }
      CAPTURE(static_cast<int>(visibility), alpha);
      const double at_grazing_view = smith_visibility(visibility, alpha, 0.0, 0.5);
      const double near_grazing_view = smith_visibility(visibility, alpha, 1e-9, 0.5);
      CHECK(std::isfinite(at_grazing_view));
      CHECK(std::abs(at_grazing_view - near_grazing_view) <= 1e-6 * at_grazing_view);
      CHECK(std::isfinite(smith_visibility(visibility, alpha, 0.5, 0.0)));
    }
  }
}

TEST_CASE("Roughness parametrizations") {
  CHECK(alpha_from(RoughnessParametrization::perceptual, 0.5) == 0.25);
  CHECK(alpha_from(RoughnessParametrization::linear, 0.5) == 0.5);
  CHECK(alpha_from(RoughnessParametrization::gloss, 0.5) == 0.0625);
  CHECK(alpha_from(RoughnessParametrization::gloss, 1.0) == 0.0);
  CHECK(alpha_from(RoughnessParametrization::gloss, 0.0) == 1.0);
  CHECK(std::string(formula(RoughnessParametrization::perceptual)) == "alpha = r^2");
  CHECK(std::string(formula(RoughnessParametrization::linear)) == "alpha = r");
  CHECK(std::string(formula(RoughnessParametrization::gloss)) == "alpha = (1 - g)^4");
}
