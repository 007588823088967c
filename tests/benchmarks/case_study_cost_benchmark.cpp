// Cost of the case-study objectives of issue 8 (sections 4, 6, 7.6, 8), one cell each: how long a cell's
// target takes to build, how long one objective evaluation takes, and what one default fit (DE + Nelder-Mead,
// optimize/fit.hpp) reaches against the course's published parameters. Not a test; figures for the sweep.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "pbrfit/brdf/disney_diffuse_course_fit.hpp"
#include "pbrfit/brdf/disney_diffuse_lobe.hpp"
#include "pbrfit/brdf/multi_lobe_sg_error.hpp"
#include "pbrfit/brdf/parallax_fit_error.hpp"
#include "pbrfit/brdf/sphere_light_models.hpp"
#include "pbrfit/brdf/sphere_light_target.hpp"
#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/optimize/fit.hpp"
#include "pbrfit/optimize/parameter_space.hpp"

using namespace pbrfit;
using Clock = std::chrono::steady_clock;

namespace {

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

optimize::FitResult fit_cell(const optimize::ParameterSpace& space, const optimize::Objective& objective,
                             std::size_t budget) {
  optimize::FitOptions options;
  options.max_evaluations = budget;
  RandomStream random(2015, 0);
  return optimize::fit(space.internal_objective(objective), space.internal_bounds(), options, random);
}

void disney() {
  integrate::AdaptiveOptions options;
  options.abs_tolerance = 1e-7;
  const auto start = Clock::now();
  double worst_beta = 0.0;
  for (int i = 0; i < 32; ++i) {
    for (int j = 0; j < 32; ++j) {
      const double roughness = i / 31.0, n_dot_v = j / 31.0;
      const brdf::DisneyDiffuseLobe lobe = brdf::disney_diffuse_lobe(roughness, n_dot_v, options);
      worst_beta = std::max(worst_beta, std::abs(lobe.beta - brdf::course_disney_beta(roughness, n_dot_v)));
    }
  }
  std::printf("disney diffuse: 32x32 cells in %.2f s; largest |beta - course beta| %.4f\n", seconds_since(start),
              worst_beta);
}

void sphere_light() {
  const double alpha = 0.1;
  const brdf::SphereLight light = brdf::sphere_light_at(0.5, 0.3);
  integrate::AdaptiveOptions options;
  options.abs_tolerance = 1e-4;
  auto start = Clock::now();
  const brdf::SphereLightTarget target(alpha, light, brdf::ViewGrid{}, options);
  const double build = seconds_since(start);
  optimize::ParameterSpace space;
  space.add({"alpha", 0.01, 1.0, optimize::Transform::log});
  space.add({"cap", 1e-2, 1e3, optimize::Transform::log});
  space.add({"s", -32.0, -1.0, optimize::Transform::linear});
  const optimize::Objective capped([&](std::span<const double> x) {
    return target.error([&](const Vector3& v) { return brdf::capped_roughness_model(x[0], x[1], x[2], light, v); }) /
           target.norm();
  });
  start = Clock::now();
  const optimize::FitResult result = fit_cell(space, capped, 2000);
  const double fitting = seconds_since(start);
  const auto x = space.from_internal(result.x);
  const double karis = target.error([&](const Vector3& v) {
    return brdf::representative_point_model(alpha, brdf::karis_sphere_normalization(alpha, light), light, v);
  }) / target.norm();
  std::printf("sphere light (alpha 0.1, gamma 0.3, incidence 0.5): target %.3f s (%zu cap evaluations, %zu views); "
              "capped fit %.4f (alpha' %.3f cap %.3g s %.1f) in %zu evaluations, %.2f s; Karis published %.4f\n",
              build, target.evaluations(), target.nodes().size(), result.value, x[0], x[1], x[2], result.evaluations,
              fitting, karis);
}

void multi_lobe(std::size_t lobes, std::size_t samples) {
  const double alpha = 0.3, theta_view = 1.2;
  auto start = Clock::now();
  const brdf::MultiLobeSgError error(alpha, std::cos(theta_view), lobes, samples);
  const double build = seconds_since(start);
  optimize::ParameterSpace space;
  space.add({"theta", 0.0, 0.5 * std::numbers::pi, optimize::Transform::cosine});
  space.add({"spread", 0.0, 0.5 * std::numbers::pi, optimize::Transform::linear});
  space.add({"lambda", 1.0, 1e4, optimize::Transform::log});
  space.add({"amplitude", 1e-3, 1e3, optimize::Transform::log});
  const optimize::Objective relative([&](std::span<const double> x) {
    return error.squared_error({x[0], x[1], x[2], x[3]}) / error.target_squared_norm();
  });
  start = Clock::now();
  const optimize::FitResult result = fit_cell(space, relative, 1000);
  const double fitting = seconds_since(start);
  const auto x = space.from_internal(result.x);
  std::printf("multi-lobe SG (N %zu, %zu samples/strategy, alpha 0.3, theta_v 1.2): target %.4f s; %.2f ms per "
              "evaluation; fit %.4f (theta %.3f spread %.3f lambda %.1f amplitude %.3g) in %zu evaluations\n",
              lobes, samples, build, 1e3 * fitting / result.evaluations, result.value, x[0], x[1], x[2], x[3],
              result.evaluations);
}

void parallax() {
  integrate::AdaptiveOptions options;
  options.abs_tolerance = 1e-7;
  optimize::ParameterSpace space;
  space.add({"alpha", 0.005, 1.0, optimize::Transform::log});
  space.add({"scale", 0.1, 10.0, optimize::Transform::log});
  space.add({"offset", -0.1, 0.1, optimize::Transform::linear});
  space.add({"shift", 0.0, 1.0, optimize::Transform::linear});
  const optimize::Objective distance([&](std::span<const double> x) {
    return brdf::distance_fit_error(0.2, 2.0, {x[0], x[1], x[2], 0.0}, 2.0, options).squared;
  });
  auto start = Clock::now();
  optimize::FitResult result = fit_cell(space, distance, 1000);
  auto x = space.from_internal(result.x);
  std::printf("parallax distance (alpha 0.2, d 2): fit %.3g (alpha' %.3f scale %.3f offset %.4f) in %zu evaluations, "
              "%.3f ms each\n",
              result.value, x[0], x[1], x[2], result.evaluations, 1e3 * seconds_since(start) / result.evaluations);
  const optimize::Objective angle([&](std::span<const double> x) {
    return brdf::angle_fit_error(0.2, 0.8, 1.0, {x[0], x[1], x[2], x[3]}, 2.0, options).squared;
  });
  start = Clock::now();
  result = fit_cell(space, angle, 1000);
  x = space.from_internal(result.x);
  std::printf("parallax angle (alpha 0.2, angle 0.8): fit %.3g (alpha' %.3f scale %.3f offset %.4f shift %.3f) in "
              "%zu evaluations, %.3f ms each\n",
              result.value, x[0], x[1], x[2], x[3], result.evaluations, 1e3 * seconds_since(start) / result.evaluations);
}

}  // namespace

int main() {
  disney();
  sphere_light();
  multi_lobe(4, 4096);
  multi_lobe(8, 4096);
  parallax();
}
