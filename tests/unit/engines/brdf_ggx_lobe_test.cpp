#include <catch2/catch_test_macros.hpp>

#include <array>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "kernel_set_scope.hpp"
#include "ltc_sphere_integration.hpp"
#include "pbrfit/core/kernel_set.hpp"
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

// GgxLobe::evaluate_many runs as vector code (brdf/ggx_lobe_batch.hpp) with the scalar code's arithmetic
// and sqrt in its order: the LTC fits, which evaluate the target through it, keep their bits in every set.
TEST_CASE("GgxLobe::evaluate_many is evaluate bit for bit in every kernel set", "[ltc]") {
  RandomStream random(2026, 12, 6);
  for (const double alpha : {1e-4, 0.02, 0.3, 1.0}) {
    for (const double cos_theta_view : {1.0, 0.7, 0.05}) {
      const GgxLobe lobe(alpha, cos_theta_view);
      std::vector<Vector3> directions;
      for (int i = 0; i < 997; ++i) {  // not a multiple of the 16 lanes: a padded last group
        const double z = 2.0 * random.uniform() - 1.0;
        const double phi = 2.0 * 3.141592653589793 * random.uniform();
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        directions.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
      }
      const Vector3 v = lobe.view();
      directions.push_back(-v);                                       // l = -v: h undefined
      directions.emplace_back(-v.x(), -v.y(), v.z());                 // the mirror direction: h = n
      directions.emplace_back(1.0, 0.0, 0.0);                         // on the horizon
      directions.emplace_back(std::sqrt(1.0 - 1e-20), 0.0, 1e-10);    // just above it
      std::vector<GgxLobe::Evaluation> scalar(directions.size());
      for (std::size_t i = 0; i < directions.size(); ++i) scalar[i] = lobe.evaluate(directions[i]);
      for (const pbrfit::KernelSet set : pbrfit::kernel_sets_available()) {
        const kernel_test::KernelSetScope scope(set);
        std::vector<GgxLobe::Evaluation> batch(directions.size());
        lobe.evaluate_many(directions, batch);
        std::size_t differing = 0;
        for (std::size_t i = 0; i < directions.size(); ++i)
          if (std::memcmp(&batch[i], &scalar[i], sizeof(GgxLobe::Evaluation)) != 0) ++differing;
        CAPTURE(pbrfit::kernel_set_name(set), alpha, cos_theta_view);
        CHECK(differing == 0);
      }
    }
  }
}
