// Environment maps: equirectangular conventions, the piecewise-constant distributions, importance
// sampling against its pdf, and estimates of known integrals; the procedural environments.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_floating_point.hpp>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/integrate/halton.hpp"
#include "pbrfit/render/environment_map.hpp"
#include "pbrfit/render/procedural_environments.hpp"

using namespace pbrfit::render;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using pbrfit::RgbImage;
using pbrfit::Vector3;

namespace {

constexpr double pi = std::numbers::pi;

// A map whose texels differ: luminance grows with the texel index, one texel black.
EnvironmentMap ramp_map(std::size_t width, std::size_t height) {
  RgbImage image(width, height);
  for (std::size_t p = 0; p < image.pixels(); ++p) image.set(p, {float(p + 1), 0.5f * float(p % 3), 0.25f});
  image.set(width + 1, {0.0f, 0.0f, 0.0f});
  return EnvironmentMap(std::move(image));
}

// The integral of pdf over the sphere, 3 x 3 points per texel (the pdf is constant on texels).
double integrated_pdf(const EnvironmentMap& map) {
  const std::size_t w = map.image().width(), h = map.image().height();
  double sum = 0.0;
  for (std::size_t row = 0; row < h; ++row)
    for (std::size_t column = 0; column < w; ++column)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          const LatLong a{(double(row) + (i + 0.5) / 3.0) * pi / double(h),
                          (double(column) + (j + 0.5) / 3.0) * 2.0 * pi / double(w)};
          sum += map.pdf(direction_of(a)) * texel_solid_angle(row, w, h) / 9.0;
        }
  return sum;
}

// Irradiance at the normal n by importance sampling at `count` Halton points.
double sampled_irradiance(const EnvironmentMap& map, const Vector3& n, std::size_t count, std::size_t channel) {
  double sum = 0.0;
  for (const auto& u : pbrfit::integrate::halton_points(count)) {
    const EnvironmentSample s = map.sample(u[0], u[1]);
    sum += s.radiance[channel] * std::max(0.0, n.dot(s.direction)) / s.pdf;
  }
  return sum / double(count);
}

// The same by quadrature, `split` x `split` midpoints per texel.
double quadrature_irradiance(const EnvironmentMap& map, const Vector3& n, int split, std::size_t channel) {
  const std::size_t w = map.image().width(), h = map.image().height();
  double sum = 0.0;
  for (std::size_t row = 0; row < h; ++row)
    for (std::size_t column = 0; column < w; ++column) {
      const double radiance = map.image().pixel(column, row)[channel];
      for (int i = 0; i < split; ++i)
        for (int j = 0; j < split; ++j) {
          const double top = std::cos((double(row) + double(i) / split) * pi / double(h));
          const double bottom = std::cos((double(row) + double(i + 1) / split) * pi / double(h));
          const double theta = std::acos(0.5 * (top + bottom));
          const double phi = (double(column) + (j + 0.5) / split) * 2.0 * pi / double(w);
          const double solid_angle = (top - bottom) * 2.0 * pi / double(w * split);
          sum += radiance * std::max(0.0, n.dot(direction_of({theta, phi}))) * solid_angle;
        }
    }
  return sum;
}

}  // namespace

TEST_CASE("equirectangular coordinates: +y up, azimuth from +z towards +x, texels tile the sphere") {
  CHECK_THAT(angles_of(Vector3::UnitY()).theta, WithinAbs(0.0, 1e-15));
  CHECK_THAT(angles_of(-Vector3::UnitY()).theta, WithinAbs(pi, 1e-15));
  CHECK_THAT(angles_of(Vector3::UnitZ()).phi, WithinAbs(0.0, 1e-15));
  CHECK_THAT(angles_of(Vector3::UnitX()).phi, WithinAbs(0.5 * pi, 1e-15));
  CHECK_THAT(angles_of(-Vector3::UnitX()).phi, WithinAbs(1.5 * pi, 1e-15));
  const Vector3 d = Vector3(0.3, -0.5, -0.7).normalized();
  CHECK((direction_of(angles_of(d)) - d).norm() < 1e-14);
  CHECK(texel_of(angles_of(-Vector3::UnitY()), 8, 4).row == 3);
  CHECK(texel_of({0.0, 2.0 * pi - 1e-17}, 8, 4).column == 7);
  CHECK(texel_of(angles_of(Vector3::UnitX()), 8, 4).column == 2);
  double total = 0.0;
  for (std::size_t row = 0; row < 5; ++row) total += 7 * texel_solid_angle(row, 7, 5);
  CHECK_THAT(total, WithinRel(4.0 * pi, 1e-14));
}

TEST_CASE("a piecewise-constant distribution samples bins by inversion and never an empty one") {
  const std::vector<double> weights = {1.0, 0.0, 3.0};
  const PiecewiseConstant d(weights);
  CHECK(d.total_weight() == 4.0);
  CHECK(d.probability(0) == 0.25);
  CHECK(d.probability(1) == 0.0);
  CHECK(d.sample(0.1).bin == 0);
  CHECK_THAT(d.sample(0.1).position, WithinAbs(0.4, 1e-15));
  CHECK(d.sample(0.25).bin == 2);
  CHECK(d.sample(0.25).position == 0.0);
  CHECK(d.sample(0.999999).bin == 2);
  CHECK(d.sample(1.0).position < 1.0);
  const std::vector<double> zeros = {0.0, 0.0};
  CHECK(PiecewiseConstant(zeros).probability(1) == 0.5);
  const std::vector<double> negative = {1.0, -1.0};
  CHECK_THROWS_AS(PiecewiseConstant(negative), std::invalid_argument);
  CHECK_THROWS_AS(PiecewiseConstant(std::vector<double>{}), std::invalid_argument);
}

TEST_CASE("an environment map reads radiance by texel and refuses maps it cannot sample") {
  const EnvironmentMap map = ramp_map(8, 4);
  CHECK(map.radiance(Vector3::UnitY())[0] == 1.0);  // row 0, column 0
  CHECK(map.radiance(Vector3::UnitX())[0] == 2 * 8 + 2 + 1);  // the equator starts row 2; +x is column 2
  CHECK(map.radiance(Vector3(-1.0, 0.01, -0.01).normalized())[0] == 1 * 8 + 5 + 1);
  CHECK(map.pdf(direction_of(texel_centre({1, 1}, 8, 4))) == 0.0);
  CHECK_THROWS_AS(EnvironmentMap(RgbImage(4, 2)), std::invalid_argument);
  CHECK_THROWS_AS(EnvironmentMap(RgbImage()), std::invalid_argument);
  CHECK_THROWS_AS(EnvironmentMap(RgbImage(2, 2, {1.0f, -1.0f, 0.0f})), std::invalid_argument);
  CHECK_THROWS_AS(EnvironmentMap(RgbImage(2, 2, {1.0f, NAN, 0.0f})), std::invalid_argument);
}

TEST_CASE("the environment pdf integrates to 1") {
  CHECK_THAT(integrated_pdf(ramp_map(8, 4)), WithinAbs(1.0, 1e-10));
  CHECK_THAT(integrated_pdf(procedural_interior()), WithinAbs(1.0, 1e-10));
  CHECK_THAT(integrated_pdf(procedural_sky()), WithinAbs(1.0, 1e-10));
}

TEST_CASE("environment samples land where the pdf says, with its value, uniformly inside texels") {
  const EnvironmentMap map = ramp_map(8, 4);
  const std::size_t count = 200'000;
  std::vector<double> observed(32, 0.0);
  std::vector<double> cos_in_row(4, 0.0), hits_in_row(4, 0.0);
  pbrfit::RandomStream random(11, 0);
  std::size_t pdf_matches = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const EnvironmentSample s = map.sample(random.uniform(), random.uniform());
    REQUIRE_THAT(s.direction.norm(), WithinAbs(1.0, 1e-10));
    const Texel t = texel_of(angles_of(s.direction), 8, 4);
    observed[t.row * 8 + t.column] += 1.0;
    const double top = std::cos(double(t.row) * pi / 4.0), bottom = std::cos(double(t.row + 1) * pi / 4.0);
    cos_in_row[t.row] += (s.direction.y() - bottom) / (top - bottom);
    hits_in_row[t.row] += 1.0;
    if (s.pdf == map.pdf(s.direction)) ++pdf_matches;
  }
  CHECK(pdf_matches >= count - 10);  // all but rounding at texel edges
  double chi_square = 0.0;
  for (std::size_t texel = 0; texel < 32; ++texel) {
    const double expected = double(count) * map.pdf(direction_of(texel_centre({texel % 8, texel / 8}, 8, 4))) *
                            texel_solid_angle(texel / 8, 8, 4);
    if (expected == 0.0) {
      CHECK(observed[texel] == 0.0);
      continue;
    }
    chi_square += (observed[texel] - expected) * (observed[texel] - expected) / expected;
  }
  CHECK(chi_square < 30 + 5 * std::sqrt(60.0));  // 30 degrees of freedom: mean 30, sd sqrt(60)
  for (std::size_t row = 0; row < 4; ++row) CHECK_THAT(cos_in_row[row] / hits_in_row[row], WithinAbs(0.5, 0.01));
}

TEST_CASE("sampled irradiance converges: pi for a constant map, the quadrature for the interior") {
  const EnvironmentMap constant(RgbImage(64, 32, {1.0f, 1.0f, 1.0f}));
  for (const Vector3& n : std::vector<Vector3>{Vector3::UnitY(), Vector3::UnitZ(), Vector3(0.6, -0.48, 0.64)}) {
    CHECK_THAT(sampled_irradiance(constant, n, 1 << 12, 0), WithinRel(pi, 3e-3));
    CHECK_THAT(sampled_irradiance(constant, n, 1 << 16, 0), WithinRel(pi, 3e-4));
  }
  const EnvironmentMap interior = procedural_interior();
  for (const Vector3& n : std::vector<Vector3>{Vector3::UnitZ(), Vector3(-0.6, 0.0, 0.8)}) {
    const double reference = quadrature_irradiance(interior, n, 4, 1);
    CHECK_THAT(sampled_irradiance(interior, n, 1 << 16, 1), WithinRel(reference, 5e-3));
  }
}

TEST_CASE("the procedural interior is a dim room lit by windows and a ceiling light; the sky has a sun") {
  const EnvironmentMap room = procedural_interior();
  CHECK(room.image().width() == 256);
  const double wall = luminance(room.radiance(direction_of({0.5 * pi - 0.3, 100.0 * pi / 180.0})));
  const double lamp = luminance(room.radiance(Vector3::UnitY()));
  const double window = luminance(room.radiance(direction_of({0.5 * pi - 0.35, 35.0 * pi / 180.0})));
  const Rgb floor = room.radiance(-Vector3::UnitY());
  CHECK(lamp > 30.0 * wall);
  CHECK(window > 30.0 * wall);
  CHECK(wall > 0.2);
  CHECK(floor[0] > floor[1]);
  CHECK(floor[1] > floor[2]);
  const EnvironmentMap sky = procedural_sky();
  const Vector3 sun = direction_of({(90.0 - 35.0) * pi / 180.0, 40.0 * pi / 180.0});
  CHECK(luminance(sky.radiance(sun)) > 1000.0 * luminance(sky.radiance(Vector3::UnitY())));
  CHECK(luminance(sky.radiance(-Vector3::UnitY())) < luminance(sky.radiance(Vector3::UnitY())));
}
