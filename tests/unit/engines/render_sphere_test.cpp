// Sphere renders: the camera's pixels, the light samples, renders of callables and of MERL tables, and
// their independence from how the pixels are split.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_floating_point.hpp>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "pbrfit/render/procedural_environments.hpp"
#include "pbrfit/render/sphere_renderer.hpp"

using namespace pbrfit::render;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using pbrfit::RgbImage;
using pbrfit::Vector3;

namespace {

constexpr double inv_pi = 1.0 / std::numbers::pi;

Rgb lambert(const Vector3&, const Vector3&) { return {inv_pi, inv_pi, inv_pi}; }

bool same_pixels(const RgbImage& a, const RgbImage& b) {
  return std::equal(a.values().begin(), a.values().end(), b.values().begin(), b.values().end());
}

}  // namespace

TEST_CASE("the sphere view's pixels: the disc, its normals and the mask") {
  const SphereView view(64);
  const auto mask = view.mask();
  std::size_t on = 0;
  for (std::size_t p = 0; p < view.pixels(); ++p) {
    on += mask[p];
    CHECK(bool(mask[p]) == view.on_sphere(p));
    if (!view.on_sphere(p)) continue;
    CHECK_THAT(view.normal(p).norm(), WithinAbs(1.0, 1e-14));
    CHECK(view.normal(p).z() > 0.0);
    CHECK_THAT(view.wo_local(p).z(), WithinAbs(view.normal(p).z(), 1e-14));
  }
  CHECK_THAT(double(on) / double(view.pixels()), WithinAbs(std::numbers::pi / 4.0, 5e-3));
  CHECK(view.normal(0).x() < 0.0);      // column 0 is on the left
  CHECK(view.normal(0).y() > 0.0);      // row 0 at the top
  CHECK(!view.on_sphere(0));
  CHECK(view.normal(32 * 64 + 32).z() > 0.999);
  CHECK_THROWS_AS(SphereView(0), std::invalid_argument);
}

TEST_CASE("a white Lambertian sphere under a constant environment of 1 has radiance 1") {
  const EnvironmentMap white(RgbImage(64, 32, {1.0f, 1.0f, 1.0f}));
  const SphereSamples samples(white, SphereView(32), 256);
  const RgbImage image = render_sphere(samples, lambert);
  const auto mask = samples.view().mask();
  double sum = 0.0, worst = 0.0;
  std::size_t on = 0;
  for (std::size_t p = 0; p < image.pixels(); ++p) {
    if (!mask[p]) {
      CHECK(image.pixel(p) == std::array<float, 3>{0.0f, 0.0f, 0.0f});
      continue;
    }
    sum += image.pixel(p)[1];
    worst = std::max(worst, std::abs(image.pixel(p)[1] - 1.0));
    ++on;
  }
  CHECK_THAT(sum / double(on), WithinAbs(1.0, 2e-3));
  CHECK(worst < 0.05);
  CHECK(samples.size() <= on * 256);
  CHECK(samples.size() > on * 100);  // about half the sphere of directions is above each horizon
}

TEST_CASE("stored samples give what the sampling loop visits; renders do not depend on the split") {
  const EnvironmentMap room = procedural_interior();
  const SphereView view(24);
  const SphereSamples samples(room, view, 64);
  std::size_t visited = 0;
  bool all_close = true;
  visit_light_samples(room, view, 64, view.all_pixels(),
                      [&](std::size_t pixel, const Vector3& wi, const Vector3& wo, const Rgb& weight) {
                        const std::size_t s = visited++;
                        all_close = all_close && s < samples.size() && s >= samples.first(pixel) &&
                                    s < samples.first(pixel + 1) && (samples.wi(s) - wi).norm() < 1e-6 &&
                                    (samples.wo(pixel) - wo).norm() == 0.0 &&
                                    std::abs(samples.weight(s)[0] - weight[0]) <= 1e-6 * weight[0] && wi.z() > 0.0;
                      });
  CHECK(visited == samples.size());
  CHECK(all_close);
  const BrdfFunction glossy = [](const Vector3& wi, const Vector3& wo) {
    const double h = (wi + wo).normalized().z();
    return Rgb{0.1 + std::pow(h, 50.0), 0.2, 0.3 * h};
  };
  const RgbImage whole = render_sphere(samples, glossy);
  RgbImage split = blank_render(samples);
  render_pixels(samples, glossy, {300, view.pixels()}, split);
  render_pixels(samples, glossy, {0, 300}, split);
  CHECK(same_pixels(whole, split));
  CHECK(same_pixels(whole, render_sphere(SphereSamples(room, view, 64), glossy)));  // deterministic
}

TEST_CASE("a MERL table renders through the stored cells; missing cells add nothing") {
  const SphereSamples samples(procedural_sky(), SphereView(16), 32);
  pbrfit::brdf::MerlTable table;
  for (std::size_t k = 0; k < 3; ++k)
    for (std::size_t c = 0; c < pbrfit::brdf::merl_cells; ++c) table.set(k, c, inv_pi);
  CHECK(same_pixels(render_sphere(samples, table), render_sphere(samples, lambert)));
  const std::size_t cell = samples.cell(samples.size() / 2);
  for (std::size_t k = 0; k < 3; ++k) table.set(k, cell, std::nan(""));
  const RgbImage with_gap = render_sphere(samples, table);
  for (float v : with_gap.values()) CHECK(std::isfinite(v));
  CHECK(with_gap.values()[0] == 0.0f);
  std::size_t same_cell = 0;  // the stored cell is that of the double-precision directions
  for (std::size_t p = 0; p < samples.view().pixels(); ++p)
    for (std::size_t s = samples.first(p); s < samples.first(p + 1); ++s)
      same_cell += pbrfit::brdf::merl_cell_of(pbrfit::brdf::to_half_diff(samples.wi(s), samples.wo(p))).flat() ==
                   samples.cell(s);
  CHECK(double(same_cell) > 0.99 * double(samples.size()));
}
