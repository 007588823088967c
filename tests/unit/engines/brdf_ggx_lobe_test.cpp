#include <catch2/catch_test_macros.hpp>

#include <array>
#include <cmath>

#include "ltc_sphere_integration.hpp"
#include "pbrfit/brdf/ggx.hpp"
#include "pbrfit/brdf/split_sum_dfg.hpp"
#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/brdf/ggx_lobe.hpp"
#include "pbrfit/ltc/lobe_moments.hpp"

using namespace pbrfit::ltc;
using pbrfit::Vector3;
using pbrfit::brdf::GgxLobe;
using pbrfit::RandomStream;
using pbrfit::brdf::SmithVisibility;
using pbrfit::test::integrate_over_sphere;

namespace {

struct Configuration {
  double alpha;
  double cos_theta_view;
};

constexpr std::array<Configuration, 4> configurations{
    {{0.3, 0.95}, {0.6, 0.4}, {0.25, 0.15}, {1.0, 0.7}}};

}  // namespace

TEST_CASE("The visible-normal sampling density integrates to 1 over the sphere", "[ltc]") {
  for (const Configuration& c : configurations) {
    const GgxLobe target(c.alpha, c.cos_theta_view);
    const auto integral =
        integrate_over_sphere<1>([&](const Vector3& l) { return std::array{target.evaluate(l).pdf}; }, 1e-8);
    CAPTURE(c.alpha, c.cos_theta_view);
    CHECK(integral.converged);
    CHECK(std::abs(integral.value[0] - 1.0) < 1e-6);
  }
}

TEST_CASE("The target is D G2 / (4 cos theta_v) and its ratio to the density is G2 / G1", "[ltc]") {
  RandomStream random(11, 0);
  for (const Configuration& c : configurations) {
    const GgxLobe target(c.alpha, c.cos_theta_view);
    const Vector3& v = target.view();
    for (int i = 0; i < 50; ++i) {
      const double u = random.uniform();
      const Vector3 l = pbrfit::test::sphere_direction(u, 6.283185307179586 * random.uniform());
      const Vector3 h = (v + l).normalized();
      const double g2 =
          pbrfit::brdf::smith_masking_shadowing(SmithVisibility::height_correlated, c.alpha, v.z(), l.z());
      const double expected = pbrfit::brdf::ggx_distribution(c.alpha, h.z()) * g2 / (4.0 * v.z());
      const GgxLobe::Evaluation e = target.evaluate(l);
      CHECK(std::abs(e.value - expected) <= 1e-12 * (1.0 + expected));
      CHECK(std::abs(e.value - e.pdf * g2 / target.view_masking()) <= 1e-12 * (1.0 + expected));
    }
  }
}

TEST_CASE("Visible-normal samples follow the density", "[ltc]") {
  for (const Configuration& c : configurations) {
    const GgxLobe target(c.alpha, c.cos_theta_view);
    const auto g = [](const Vector3& l) { return std::array{l.z() + 1.0, l.x() * l.x(), std::exp(l.x())}; };
    const auto expected = integrate_over_sphere<3>(
        [&](const Vector3& l) {
          const double pdf = target.evaluate(l).pdf;
          const auto values = g(l);
          return std::array{pdf * values[0], pdf * values[1], pdf * values[2]};
        },
        1e-8);
    RandomStream random(12, 0);
    constexpr int count = 200'000;
    std::array<double, 3> sum{};
    std::array<double, 3> sum_squares{};
    for (int i = 0; i < count; ++i) {
      const double u1 = random.uniform();
      const auto values = g(target.sample(u1, random.uniform()));
      for (int k = 0; k < 3; ++k) {
        sum[k] += values[k];
        sum_squares[k] += values[k] * values[k];
      }
    }
    for (int k = 0; k < 3; ++k) {
      const double mean = sum[k] / count;
      const double standard_error = std::sqrt((sum_squares[k] / count - mean * mean) / count);
      CAPTURE(c.alpha, c.cos_theta_view, k, mean, expected.value[k]);
      CHECK(std::abs(mean - expected.value[k]) < 4.0 * standard_error + 1e-7);
    }
  }
}

TEST_CASE("Albedo and Fresnel term match the independent split-sum integrator", "[ltc]") {
  for (const Configuration& c : configurations) {
    const GgxLobe target(c.alpha, c.cos_theta_view);
    const LobeMoments moments = measure_moments(target, 4096);
    const auto dfg = pbrfit::brdf::integrate_dfg(c.cos_theta_view, c.alpha, SmithVisibility::height_correlated,
                                                 pbrfit::integrate::AdaptiveOptions{1e-9});
    CAPTURE(c.alpha, c.cos_theta_view, moments.albedo, dfg.scale + dfg.bias);
    CHECK(std::abs(moments.albedo - (dfg.scale + dfg.bias)) < 2e-4);
    CHECK(std::abs(moments.fresnel - dfg.bias) < 1e-4);
  }
}

TEST_CASE("The average direction matches cubature and lies in the x-z plane on the mirror side", "[ltc]") {
  for (const Configuration& c : configurations) {
    const GgxLobe target(c.alpha, c.cos_theta_view);
    const auto first_moment = integrate_over_sphere<3>(
        [&](const Vector3& l) {
          const double value = target.evaluate(l).value;
          return std::array{value * l.x(), value * l.y(), value * l.z()};
        },
        1e-8);
    const Vector3 expected = Vector3(first_moment.value[0], 0.0, first_moment.value[2]).normalized();
    const Vector3 measured = measure_moments(target, 4096).average_direction;
    CAPTURE(c.alpha, c.cos_theta_view, measured.transpose(), expected.transpose());
    CHECK(measured.y() == 0.0);
    CHECK((measured - expected).norm() < 1e-3);
    CHECK(measured.x() <= 1e-4);  // at alpha = 1 the lobe is centred on the normal
  }
}

TEST_CASE("The target rejects alpha <= 0 and views at or below the horizon", "[ltc]") {
  CHECK_THROWS_AS(GgxLobe(0.0, 0.5), std::invalid_argument);
  CHECK_THROWS_AS(GgxLobe(0.5, 0.0), std::invalid_argument);
  CHECK_THROWS_AS(GgxLobe(0.5, 1.5), std::invalid_argument);
}
