#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <numbers>
#include <set>

#include "pbrfit/ebrdf/albedo_curve.hpp"
#include "pbrfit/ebrdf/base_lobe.hpp"
#include "pbrfit/ebrdf/footprint_samples.hpp"
#include "pbrfit/ebrdf/procedural_normal_maps.hpp"
#include "pbrfit/ebrdf/view_grid.hpp"

using namespace pbrfit::ebrdf;
using pbrfit::RandomStream;
using pbrfit::Vector3;

namespace {

Vector3 mean_direction(const std::vector<Vector3>& samples) {
  Vector3 sum = Vector3::Zero();
  for (const auto& s : samples) sum += s;
  return sum.normalized();
}

NormalMap flat_map(std::size_t size) { return NormalMap(size, std::vector<Vector3>(size * size, Vector3::UnitZ())); }

}  // namespace

TEST_CASE("the view grid follows the thesis' elevations and covers the circle once") {
  const ViewGrid grid{8, 16};
  CHECK(grid.theta(0) == 0.0);
  CHECK(grid.theta(7) == Catch::Approx(0.999 * std::numbers::pi / 2));
  CHECK(grid.phi(15) == Catch::Approx(2 * std::numbers::pi * 15 / 16));
  CHECK(ViewGrid{1, 1}.theta(0) == 0.1);
  const Vector3 v = grid.direction(3 * 16 + 4);
  CHECK(v.z() == Catch::Approx(std::cos(grid.theta(3))));
  CHECK(std::atan2(v.y(), v.x()) == Catch::Approx(grid.phi(4)));
  CHECK(rotate_azimuth_to_zero(v, grid.phi(4)).y() == Catch::Approx(0.0).margin(1e-12));
}

TEST_CASE("a base lobe is sampled in the texel's frame and lands around its reflection") {
  const Vector3 n = Vector3(0.3, -0.2, 1.0).normalized();
  const Vector3 v = Vector3(-0.5, 0.1, 0.8).normalized();
  RandomStream random(1, 2);
  const auto specular = sample_base_lobe({Component::specular, 0.01}, n, v, 256, random);
  REQUIRE(specular.size() == 256);
  CHECK((mean_direction(specular) - (2 * v.dot(n) * n - v)).norm() < 0.02);
  for (const auto& l : specular) CHECK(l.dot(n) > 0.0);
  const auto diffuse = sample_base_lobe({Component::diffuse, 0.01}, n, v, 4096, random);
  double mean_cos = 0.0;
  for (const auto& l : diffuse) mean_cos += l.dot(n) / 4096.0;
  CHECK(mean_cos == Catch::Approx(2.0 / 3.0).margin(0.01));
  RandomStream same(1, 2);
  CHECK(sample_base_lobe({Component::specular, 0.01}, n, v, 256, same) == specular);
}

TEST_CASE("a footprint pools its texels' lobes: all of them, or a fixed subset, rotated to azimuth 0") {
  const NormalMap map = procedural_normal_map(NormalPattern::glitter, 32, 5);
  const EbrdfSampling sampling{{Component::specular, 0.01}, {4, 8}, 128, 9};
  const AlbedoCurve albedo(sampling.lobe);
  const FootprintSampler sampler(map, sampling, albedo);
  CHECK(mip_levels(32) == 5);
  CHECK(mip_side(32, 5) == 1);

  const auto level1 = sampler.contributing_texels({1, 3, 2});
  CHECK(level1 == std::vector<std::size_t>{6 + 4 * 32, 7 + 4 * 32, 6 + 5 * 32, 7 + 5 * 32});
  const auto level5 = sampler.contributing_texels({5, 0, 0});
  CHECK(level5.size() == 128);
  CHECK(std::set<std::size_t>(level5.begin(), level5.end()).size() == 128);

  // The pooled set holds each texel's own samples (first samples first), azimuth-rotated.
  const std::size_t view = 2 * 8 + 3;
  const auto pooled = sampler.samples(level1, view);
  REQUIRE(pooled.size() == 128);
  RandomStream stream(9, level1[1], view);
  const auto lobe = sample_base_lobe(sampling.lobe, map.normals()[level1[1]], sampling.views.direction(view), 32, stream);
  CHECK((pooled[1] - rotate_azimuth_to_zero(lobe[0], sampling.views.phi(3))).norm() < 1e-15);
  CHECK((pooled[5] - rotate_azimuth_to_zero(lobe[1], sampling.views.phi(3))).norm() < 1e-15);
}

TEST_CASE("on a flat map every level's eBRDF is the base lobe, with the lobe's albedo as amplitude") {
  const NormalMap map = flat_map(16);
  const EbrdfSampling sampling{{Component::specular, 0.02}, {4, 4}, 256, 2};
  const AlbedoCurve albedo(sampling.lobe);
  const FootprintSampler sampler(map, sampling, albedo);
  for (std::size_t level : {1, 4}) {
    const std::size_t view = 2 * 4 + 1;
    const Vector3 v = sampling.views.direction(view);
    const auto samples = sampler.samples(sampler.contributing_texels({level, 0, 0}), view);
    const Vector3 mirror = rotate_azimuth_to_zero(Vector3(-v.x(), -v.y(), v.z()), sampling.views.phi(1));
    CHECK((mean_direction(samples) - mirror).norm() < 0.03);
    CHECK(sampler.amplitude({level, 0, 0}, view) == Catch::Approx(albedo.at(v.z())));
  }
  CHECK(albedo.at(1.0) > 0.9);
  CHECK(albedo.at(1.0) <= 1.0);
  CHECK(AlbedoCurve({Component::diffuse, 0.1}).at(0.3) == 1.0);
}
