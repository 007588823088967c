#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <numbers>

#include "pbrfit/brdf/ggx_lobe.hpp"
#include "pbrfit/brdf/sphere_light.hpp"
#include "pbrfit/brdf/sphere_light_models.hpp"
#include "pbrfit/brdf/sphere_light_target.hpp"
#include "pbrfit/brdf/split_sum_dfg.hpp"

using namespace pbrfit::brdf;
using pbrfit::integrate::AdaptiveOptions;
using pbrfit::Vector3;

namespace {

AdaptiveOptions with_tolerance(double tolerance) {
  AdaptiveOptions options;
  options.abs_tolerance = tolerance;
  return options;
}

Vector3 view_at(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}


}  // namespace

TEST_CASE("a vanishing spherical light tends to the point light", "[sphere_light]") {
  const SphereLight light = sphere_light_at(0.5, 1e-3);
  for (const Vector3& view : {view_at(0.4, 0.0), view_at(0.6, 0.3), view_at(1.2, 2.0)}) {
    for (double alpha : {0.1, 0.5}) {
      const SphereLightResponse response = sphere_light_response(alpha, light, view, with_tolerance(1e-9));
      const double point = ggx_cosine_weighted(alpha, view, light.centre);
      CAPTURE(alpha, response.value, point);
      REQUIRE(response.converged);
      CHECK(std::abs(response.value - point) <= 1e-4 * point + 1e-9);
    }
  }
}

TEST_CASE("a hemispherical light around the normal integrates to the directional albedo", "[sphere_light]") {
  const SphereLight sky = sphere_light_at(0.0, 0.5 * std::numbers::pi);
  for (double alpha : {0.2, 0.7}) {
    for (double theta : {0.2, 1.1}) {
      const Vector3 view = view_at(theta, 0.0);
      const SphereLightResponse response = sphere_light_response(alpha, sky, view, with_tolerance(1e-8));
      const DfgEntry dfg = integrate_dfg(view.z(), alpha, SmithVisibility::height_correlated, with_tolerance(1e-9));
      CAPTURE(alpha, theta);
      // radiance 1/(2 pi) over the hemisphere: 2 pi response = integral of rho = scale + bias.
      CHECK(std::abs(2.0 * std::numbers::pi * response.value - (dfg.scale + dfg.bias)) < 1e-6);
    }
  }
}

TEST_CASE("the view quadrature integrates known functions", "[sphere_light]") {
  const SphereLightTarget target(0.3, sphere_light_at(0.7, 0.2), ViewGrid{}, with_tolerance(1e-3));
  double solid_angle = 0.0, first_moment = 0.0;
  for (const auto& node : target.nodes()) {
    solid_angle += node.weight;
    first_moment += node.weight * std::max(0.0, node.view.z());
  }
  CHECK(std::abs(solid_angle - 4.0 * std::numbers::pi) < 1e-6);
  CHECK(std::abs(first_moment - std::numbers::pi) < 1e-3);  // the horizon kink limits the rule
}

TEST_CASE("soft minimum tends to the minimum and stays below it", "[sphere_light]") {
  CHECK(soft_minimum(2.0, 3.0, -8.0) < 2.0);
  CHECK(std::abs(soft_minimum(2.0, 3.0, -200.0) - 2.0) < 1e-6);
  CHECK(soft_minimum(2.0, 3.0, -3.0) == soft_minimum(3.0, 2.0, -3.0));
  CHECK(soft_minimum(0.0, 3.0, -3.0) == 0.0);
  CHECK(std::abs(soft_minimum(1e-300, 1.0, -10.0) - 1e-300) < 1e-310);
}

TEST_CASE("the published sphere-light models are close to ground truth for small lights", "[sphere_light]") {
  for (double incidence : {0.0, 0.8}) {
    const SphereLight light = sphere_light_at(incidence, 0.05);
    const double alpha = 0.6;
    const SphereLightTarget target(alpha, light, ViewGrid{}, with_tolerance(1e-5));
    REQUIRE(target.converged());
    const double norm = target.norm();
    const double point = target.error([&](const Vector3& v) { return roughness_modification_model(alpha, light, v); });
    const double karis = target.error([&](const Vector3& v) {
      return representative_point_model(alpha, karis_sphere_normalization(alpha, light), light, v);
    });
    const double smoothed = target.error([&](const Vector3& v) {
      return smoothed_representative_point_model(alpha, course_smoothed_normalization(alpha, light),
                                                 course_representative_smoothness, light, v);
    });
    CAPTURE(incidence, point / norm, karis / norm, smoothed / norm);
    CHECK(point / norm < 0.01);
    CHECK(karis / norm < 0.05);
    CHECK(smoothed / norm < 0.06);
  }
}

TEST_CASE("larger lights call for rougher lobes and smoothed representative points", "[sphere_light]") {
  const double alpha = 0.1;
  const SphereLight light = sphere_light_at(0.0, 0.5);
  const SphereLightTarget target(alpha, light, ViewGrid{}, with_tolerance(1e-4));
  const auto modified = [&](double alpha_modified) {
    return target.error([&](const Vector3& v) { return roughness_modification_model(alpha_modified, light, v); });
  };
  CHECK(modified(0.2) < 0.5 * modified(alpha));  // the fitted roughness grows with the light

  // A cap on the modified lobe reproduces the plateau of wide lights: better than any uncapped lobe tried.
  double best_uncapped = modified(alpha);
  for (double a = alpha; a < 0.6; a *= 1.05) best_uncapped = std::min(best_uncapped, modified(a));
  const auto capped_unit = [&](double cap) {
    return [&, cap](const Vector3& v) { return capped_roughness_model(0.2, cap, course_capped_smoothness, light, v); };
  };
  double best_capped = target.error(capped_unit(1e9));
  for (double cap = 0.2; cap < 4.0; cap *= 1.1) best_capped = std::min(best_capped, target.error(capped_unit(cap)));
  CAPTURE(best_uncapped / target.norm(), best_capped / target.norm());
  CHECK(best_capped < best_uncapped);

  // With their least-squares normalization, the soft minimum beats Karis' hard clamp on a wide light.
  const auto hard = [&](const Vector3& v) { return representative_point_model(alpha, 1.0, light, v); };
  const auto soft = [&](const Vector3& v) {
    return smoothed_representative_point_model(alpha, 1.0, course_representative_smoothness, light, v);
  };
  const double hard_scale = target.least_squares_scale(hard), soft_scale = target.least_squares_scale(soft);
  const double hard_error = target.error([&](const Vector3& v) { return hard_scale * hard(v); });
  const double soft_error = target.error([&](const Vector3& v) { return soft_scale * soft(v); });
  CAPTURE(hard_error / target.norm(), soft_error / target.norm());
  CHECK(soft_error < 0.5 * hard_error);
}
