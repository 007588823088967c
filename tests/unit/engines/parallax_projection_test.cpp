#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "pbrfit/brdf/ggx_lobe.hpp"
#include "pbrfit/brdf/parallax_fit_error.hpp"
#include "pbrfit/brdf/projected_lobe.hpp"
#include "pbrfit/integrate/direction_domain.hpp"

using namespace pbrfit::brdf;
using pbrfit::integrate::AdaptiveOptions;
using pbrfit::Vector3;

namespace {

AdaptiveOptions with_tolerance(double tolerance) {
  AdaptiveOptions options;
  options.abs_tolerance = tolerance;
  return options;
}

}  // namespace

TEST_CASE("a projected lobe carries the energy of the cone of directions that hits the disk", "[parallax]") {
  const double alpha = 0.3, distance = 1.5, radius = 2.0;
  const ProjectedLobe lobe = perpendicular_lobe(alpha, distance);
  const std::array<pbrfit::integrate::Box<1>, 3> tiles{{{{0.0}, {0.1}}, {{0.1}, {0.5}}, {{0.5}, {radius}}}};
  const auto on_plane = pbrfit::integrate::integrate_adaptive<1, 1>(
      [&](const std::array<double, 1>& r) {
        return std::array<double, 1>{2.0 * std::numbers::pi * r[0] * lobe.density(r[0], 0.0)};
      },
      std::span<const pbrfit::integrate::Box<1>>(tiles), with_tolerance(1e-10));
  const double cos_edge = distance / std::hypot(distance, radius);
  const auto in_cone = pbrfit::integrate::integrate_over_directions<1>(
      [&](const pbrfit::integrate::UnitDirection& d) {
        return std::array<double, 1>{ggx_cosine_weighted(alpha, Vector3::UnitZ(), Vector3(d[0], d[1], d[2]))};
      },
      cos_edge, 1.0, 4, with_tolerance(1e-10));
  CHECK(std::abs(on_plane.value[0] - in_cone.value[0]) < 1e-8);
}

TEST_CASE("a lobe tilted by 0 is the perpendicular lobe", "[parallax]") {
  const ProjectedLobe tilted = tilted_lobe(0.2, 0.0, 1.3), perpendicular = perpendicular_lobe(0.2, 1.3);
  for (double x : {-0.7, 0.0, 0.2}) {
    for (double y : {0.0, 0.4}) CHECK(std::abs(tilted.density(x, y) - perpendicular.density(x, y)) < 1e-12);
  }
}

TEST_CASE("the parallax errors vanish for the source itself and match a brute-force sum", "[parallax]") {
  const AdaptiveOptions options = with_tolerance(1e-9);
  CHECK(distance_fit_error(0.2, 1.0, {0.2, 1.0, 0.0, 0.0}, 2.0, options).squared == 0.0);
  CHECK(angle_fit_error(0.2, 0.0, 1.0, {0.2, 1.0, 0.0, 0.7}, 2.0, options).squared == 0.0);

  const double alpha = 0.5, angle = 0.5, window = 1.0;
  const PerpendicularCandidate candidate{0.4, 1.1, 0.01, 0.3};
  const ProjectionError adaptive = angle_fit_error(alpha, angle, 1.0, candidate, window, options);
  REQUIRE(adaptive.converged);
  const ProjectedLobe source = tilted_lobe(alpha, angle, 1.0);
  const ProjectedLobe fitted = perpendicular_lobe(0.4, 1.0, -0.3 * std::sin(angle));
  const int n = 600;
  const double h = 2.0 * window / n;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const double x = -window + (i + 0.5) * h, y = -window + (j + 0.5) * h;
      const double difference = source.density(x, y) - (1.1 * fitted.density(x, y) + 0.01);
      sum += difference * difference * h * h;
    }
  }
  CAPTURE(adaptive.squared, sum);
  CHECK(std::abs(adaptive.squared / sum - 1.0) < 1e-3);
}

TEST_CASE("farther lobes match rougher perpendicular lobes at unit distance", "[parallax]") {
  const AdaptiveOptions options = with_tolerance(1e-8);
  const auto best_alpha = [&](double alpha, double distance) {
    double best = INFINITY, argmin = 0.0;
    for (double candidate = 0.02; candidate < 1.0; candidate *= 1.02) {
      const double squared = distance_fit_error(alpha, distance, {candidate, 1.0, 0.0, 0.0}, 2.0, options).squared;
      if (squared < best) best = squared, argmin = candidate;
    }
    return argmin;
  };
  // Near the diagonal alpha' ~ alpha * distance (the projection of a lobe scales with its distance).
  const double farther = best_alpha(0.2, 2.0), nearer = best_alpha(0.2, 0.5);
  CAPTURE(farther, nearer);
  CHECK(farther > 0.3);
  CHECK(farther < 0.45);
  CHECK(nearer > 0.07);
  CHECK(nearer < 0.13);
}

TEST_CASE("the shift lets a perpendicular lobe follow a tilted one", "[parallax]") {
  const AdaptiveOptions options = with_tolerance(1e-7);
  const double alpha = 0.3, angle = 1.0;
  const auto error_at = [&](double shift) {
    return angle_fit_error(alpha, angle, 1.0, {0.32, 1.0, 0.0, shift}, 2.0, options).squared;
  };
  double best_shifted = INFINITY;
  for (double shift = 0.1; shift <= 1.0; shift += 0.1) best_shifted = std::min(best_shifted, error_at(shift));
  CAPTURE(best_shifted, error_at(0.0));
  CHECK(best_shifted < 0.8 * error_at(0.0));
}
