#include <catch2/catch_test_macros.hpp>

#include <array>
#include <cmath>
#include <numbers>

#include "ltc_sphere_integration.hpp"
#include "pbrfit/brdf/ggx_lobe.hpp"
#include "pbrfit/brdf/tabulated_lobe.hpp"
#include "pbrfit/core/random_stream.hpp"

using namespace pbrfit::brdf;
using pbrfit::RandomStream;
using pbrfit::Vector3;
using pbrfit::test::integrate_over_sphere;

namespace {

// A lobe only known by its values: GGX, or a retro-reflective lobe peaked at the view.
TabulatedLobe::Function ggx_values(double alpha, double cos_v) {
  const Vector3 v = view_in_xz_plane(cos_v);
  return [alpha, v](const Vector3& l) { return ggx_cosine_weighted(alpha, v, l); };
}

TabulatedLobe::Function retro_values(double cos_v) {
  const Vector3 v = view_in_xz_plane(cos_v);
  return [v](const Vector3& l) { return l.z() > 0.0 ? 20.0 * std::pow(std::max(0.0, l.dot(v)), 40.0) * l.z() : 0.0; };
}

}  // namespace

TEST_CASE("A tabulated lobe's density integrates to 1 and is positive where the lobe is", "[brdf]") {
  RandomStream random(7, 0);
  for (double c : {1.0, 0.5, 0.1}) {
    for (const auto& rho : {ggx_values(0.05, c), ggx_values(0.6, c), retro_values(c)}) {
      const TabulatedLobe lobe(c, rho);
      // A piecewise-constant density: cubature converges slowly across its cells' edges.
      const auto integral =
          integrate_over_sphere<1>([&](const Vector3& l) { return std::array{lobe.evaluate(l).pdf}; }, 1e-4, 2'000'000);
      CAPTURE(c, integral.value[0], integral.error_estimate);
      CHECK(std::abs(integral.value[0] - 1.0) < 2e-3);
      for (int i = 0; i < 500; ++i) {
        const double u = random.uniform();
        const Vector3 l = pbrfit::test::sphere_direction(u, 2.0 * std::numbers::pi * random.uniform());
        const auto e = lobe.evaluate(l);
        if (e.value > 0.0) CHECK(e.pdf > 0.0);
      }
    }
  }
}

TEST_CASE("A tabulated lobe samples its density and finds its peak", "[brdf]") {
  const double c = 0.5;
  const TabulatedLobe lobe(c, retro_values(c));
  CHECK((*lobe.peak() - view_in_xz_plane(c)).norm() < 0.05);
  // The importance-sampled integral of rho matches cubature.
  const auto albedo = integrate_over_sphere<1>([&](const Vector3& l) { return std::array{lobe.value(l)}; }, 1e-9, 20'000'000);
  RandomStream random(8, 0);
  constexpr int count = 100'000;
  double sum = 0.0, sum_squares = 0.0;
  for (int i = 0; i < count; ++i) {
    const double u1 = random.uniform();
    const Vector3 l = lobe.sample(u1, random.uniform());
    CHECK(std::abs(l.norm() - 1.0) < 1e-12);
    const auto e = lobe.evaluate(l);
    REQUIRE(e.pdf > 0.0);
    const double w = e.value / e.pdf;
    sum += w;
    sum_squares += w * w;
  }
  const double mean = sum / count;
  const double standard_error = std::sqrt((sum_squares / count - mean * mean) / count);
  CAPTURE(mean, albedo.value[0], standard_error);
  CHECK(std::abs(mean - albedo.value[0]) < 4.0 * standard_error);
  CHECK(standard_error < 0.01 * albedo.value[0]);  // the table follows the lobe: a low-variance estimate
}

TEST_CASE("A tabulated lobe refuses negative values and falls back to cosine sampling for a zero lobe", "[brdf]") {
  CHECK_THROWS_AS(TabulatedLobe(0.5, [](const Vector3&) { return -1.0; }), std::invalid_argument);
  const TabulatedLobe zero(0.5, [](const Vector3&) { return 0.0; });
  const Vector3 l(0.0, 0.6, 0.8);
  CHECK(std::abs(zero.evaluate(l).pdf - 0.8 / std::numbers::pi) < 1e-15);
}
