#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <numbers>

#include "pbrfit/brdf/multi_lobe_sg.hpp"
#include "pbrfit/brdf/multi_lobe_sg_error.hpp"
#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/integrate/direction_domain.hpp"
#include "pbrfit/integrate/halton.hpp"
#include "pbrfit/integrate/mis_estimator.hpp"
#include "pbrfit/optimize/fit.hpp"
#include "pbrfit/optimize/parameter_space.hpp"

using namespace pbrfit::brdf;
using pbrfit::Vector3;

namespace {

constexpr double pi = std::numbers::pi;

struct UniformSphere {
  Vector3 sample(double u1, double u2) const {
    const auto d = pbrfit::integrate::direction_from(1.0 - 2.0 * u1, 2.0 * pi * u2);
    return {d[0], d[1], d[2]};
  }
  double pdf(const Vector3&) const { return 0.25 / pi; }
};

}  // namespace

TEST_CASE("SG sampling inverts its CDF and its pdf integrates to 1", "[multi_lobe_sg]") {
  const SphericalGaussian lobe{Vector3(0.6, 0.0, 0.8), 25.0, 2.0};
  // The fraction of samples within angle t of the axis is the CDF (1 - e^{-lambda (1 - cos t)}) / (1 - e^{-2 lambda}).
  const auto points = pbrfit::integrate::halton_points(20000);
  const double cos_t = std::cos(0.2);
  double inside = 0.0;
  for (const auto& u : points) inside += lobe.sample(u[0], u[1]).dot(lobe.axis) > cos_t ? 1.0 : 0.0;
  const double cdf = -std::expm1(-25.0 * (1.0 - cos_t)) / -std::expm1(-50.0);
  CHECK(std::abs(inside / points.size() - cdf) < 1e-3);
  // Closed-form integral against adaptive cubature.
  pbrfit::integrate::AdaptiveOptions options;
  options.abs_tolerance = 1e-9;
  const auto cubature = pbrfit::integrate::integrate_over_directions<2>(
      [&](const pbrfit::integrate::UnitDirection& d) {
        const Vector3 w(d[0], d[1], d[2]);
        return std::array<double, 2>{lobe.value(w), lobe.pdf(w)};
      },
      -1.0, 1.0, 8, options);
  CHECK(std::abs(cubature.value[0] - lobe.integral()) < 1e-7);
  CHECK(std::abs(cubature.value[1] - 1.0) < 1e-7);
}

TEST_CASE("balance-heuristic QMC integrates a lobe with a mixture of strategies", "[multi_lobe_sg]") {
  const SphericalGaussian lobe{Vector3(0.0, 0.6, 0.8), 40.0, 1.5};
  const auto points = pbrfit::integrate::halton_points(4096);
  // Two different strategy types behind one interface: a variant-like wrapper.
  struct Either {
    const SphericalGaussian* lobe;
    Vector3 sample(double u1, double u2) const { return lobe ? lobe->sample(u1, u2) : UniformSphere{}.sample(u1, u2); }
    double pdf(const Vector3& w) const { return lobe ? lobe->pdf(w) : UniformSphere{}.pdf(w); }
  };
  const std::array<Either, 2> strategies{Either{&lobe}, Either{nullptr}};
  const auto square = [&](const Vector3& w) { return lobe.value(w) * lobe.value(w); };
  // integral of SG^2 = SG with twice the sharpness and squared amplitude.
  const SphericalGaussian squared{lobe.axis, 2.0 * lobe.sharpness, lobe.amplitude * lobe.amplitude};
  const double estimate = pbrfit::integrate::integrate_balance_mis(square, std::span<const Either>(strategies),
                                                                   std::span<const std::array<double, 2>>(points));
  CHECK(std::abs(estimate / squared.integral() - 1.0) < 2e-3);
}

TEST_CASE("multi-lobe SG kernel follows the course's lobe layout and constraint", "[multi_lobe_sg]") {
  const MultiLobeSgParameters parameters{0.6, 0.3, 30.0, 2.0};
  const auto lobes = multi_lobe_sg_lobes(parameters, 4);
  REQUIRE(lobes.size() == 4);
  // Lobe angles span theta_center -+ spread, across the normal from v (negative x).
  CHECK(std::abs(std::atan2(-lobes.front().axis.x(), lobes.front().axis.z()) - 0.3) < 1e-12);
  CHECK(std::abs(std::atan2(-lobes.back().axis.x(), lobes.back().axis.z()) - 0.9) < 1e-12);
  CHECK(lobes.front().amplitude == lobes.back().amplitude);  // symmetric amplitudes
  CHECK(lobes.front().amplitude < lobes[1].amplitude);
  // spread beyond theta_center is clamped to it.
  const auto clamped = multi_lobe_sg_lobes({0.2, 0.5, 30.0, 2.0}, 6);
  const auto at_limit = multi_lobe_sg_lobes({0.2, 0.2, 30.0, 2.0}, 6);
  for (std::size_t i = 0; i < 6; ++i) {
    CHECK(clamped[i].axis == at_limit[i].axis);
    CHECK(clamped[i].amplitude == at_limit[i].amplitude);
  }
  const auto normalized = multi_lobe_sg_lobes(normalized_to(parameters, 4, 0.8), 4);
  CHECK(std::abs(multi_lobe_sg_integral(normalized) - 0.8) < 1e-12);
}

TEST_CASE("the MIS error of a multi-lobe kernel matches adaptive cubature over the sphere", "[multi_lobe_sg]") {
  for (const double theta_view : {0.3, 1.2}) {
    const MultiLobeSgError error(0.4, std::cos(theta_view), 4, 4096);
    const MultiLobeSgParameters parameters{theta_view, 0.2, 8.0, 1.0};
    const auto lobes = multi_lobe_sg_lobes(normalized_to(parameters, 4, error.target_integral()), 4);
    pbrfit::integrate::AdaptiveOptions options;
    options.abs_tolerance = 1e-7;
    const auto reference = pbrfit::integrate::integrate_over_directions<2>(
        [&](const pbrfit::integrate::UnitDirection& d) {
          const Vector3 w(d[0], d[1], d[2]);
          const double rho = error.target().evaluate(w).value;
          const double difference = rho - multi_lobe_sg_value(lobes, w);
          return std::array<double, 2>{difference * difference, rho};
        },
        -1.0, 1.0, 8, options);
    CAPTURE(theta_view, error.squared_error_normalized(parameters), reference.value[0]);
    CHECK(std::abs(error.target_integral() - reference.value[1]) < 1e-6);
    CHECK(std::abs(error.squared_error_normalized(parameters) / reference.value[0] - 1.0) < 5e-3);
    CHECK(error.squared_error_normalized(parameters) == error.squared_error_normalized(parameters));
  }
}

TEST_CASE("spread lets the multi-lobe kernel follow the elongated lobe of grazing views", "[multi_lobe_sg]") {
  using namespace pbrfit::optimize;
  const double theta_view = 1.3;
  const MultiLobeSgError error(0.3, std::cos(theta_view), 4, 1024);
  const auto best = [&](double max_spread) {
    ParameterSpace space;
    space.add({"theta", 0.0, 1.5, Transform::cosine});
    space.add({"spread", 0.0, max_spread, Transform::linear});
    space.add({"lambda", 1.0, 1e4, Transform::log});
    const Objective relative([&](std::span<const double> x) {
      return error.squared_error_normalized({x[0], x[1], x[2], 1.0}) / error.target_squared_norm();
    });
    FitOptions options;
    options.max_evaluations = 400;
    pbrfit::RandomStream random(7, 0);
    return fit(space.internal_objective(relative), space.internal_bounds(), options, random).value;
  };
  const double single_direction = best(0.0), spread = best(1.0);
  CAPTURE(single_direction, spread);
  CHECK(spread < 0.9 * single_direction);
}
