#include <catch2/catch_test_macros.hpp>

#include <array>
#include <cmath>

#include "ltc_sphere_integration.hpp"
#include "pbrfit/brdf/cloth_albedo.hpp"
#include "pbrfit/brdf/sheen.hpp"

using namespace pbrfit::brdf;
using pbrfit::Vector3;

TEST_CASE("The cloth albedo matches cubature over the sphere of the Charlie-Neubelt lobe", "[brdf]") {
  for (double alpha : {0.05, 0.3, 1.0}) {
    for (double mu : {1.0, 0.5, 0.1}) {
      const Vector3 v(std::sqrt(1.0 - mu * mu), 0.0, mu);
      const auto reference = pbrfit::test::integrate_over_sphere<1>(
          [&](const Vector3& l) {
            if (!(l.z() > 0.0)) return std::array{0.0};
            const double n_dot_h = (v + l).normalized().z();
            return std::array{charlie_distribution(alpha, n_dot_h) * neubelt_visibility(mu, l.z()) * l.z()};
          },
          1e-9, 50'000'000);
      pbrfit::integrate::AdaptiveOptions options;
      options.abs_tolerance = 1e-8;
      const ClothAlbedo cloth = integrate_cloth_albedo(mu, alpha, options);
      CAPTURE(alpha, mu, cloth.value, reference.value[0], cloth.evaluations);
      CHECK(cloth.converged);
      CHECK(std::abs(cloth.value - reference.value[0]) < 1e-7);
    }
  }
}

TEST_CASE("The cloth albedo converges at low roughness and grazing views, and is 0 at alpha = 0", "[brdf]") {
  pbrfit::integrate::AdaptiveOptions options;
  options.abs_tolerance = 1e-6;
  for (double alpha : {1e-4, 1e-3, 0.01}) {
    for (double mu : {0.0, 0.003, 0.05, 0.7}) {
      const ClothAlbedo cloth = integrate_cloth_albedo(mu, alpha, options);
      CAPTURE(alpha, mu, cloth.value, cloth.error_estimate, cloth.evaluations);
      CHECK(cloth.converged);
      CHECK(cloth.value >= 0.0);
    }
  }
  CHECK(integrate_cloth_albedo(0.5, 0.0, options).value == 0.0);
  CHECK_THROWS_AS(integrate_cloth_albedo(1.5, 0.3, options), std::invalid_argument);
}
