#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "pbrfit/brdf/split_sum_dfg.hpp"

#include "pbrfit/ebrdf/base_lobe.hpp"
#include "pbrfit/ebrdf/footprint_samples.hpp"
#include "pbrfit/ebrdf/procedural_normal_maps.hpp"
#include "pbrfit/ebrdf/view_grid.hpp"

using namespace pbrfit::ebrdf;
using pbrfit::Vector3;

namespace {

Vector3 mean_direction(const std::vector<Vector3>& samples) {
  Vector3 sum = Vector3::Zero();
  for (const auto& s : samples) sum += s;
  return sum.normalized();
}

NormalMap flat_map(std::size_t size) { return NormalMap(size, std::vector<Vector3>(size * size, Vector3::UnitZ())); }

}  // namespace

TEST_CASE("the view grid spans the thesis' elevations, crowds them towards grazing and covers the circle once") {
  const ViewGrid grid{8, 16};
  CHECK(grid.theta(0) == 0.0);
  CHECK(grid.theta(7) == Catch::Approx(0.999 * std::numbers::pi / 2));
  CHECK(grid.theta(3) == Catch::Approx(0.999 * std::numbers::pi / 2 * std::sin(3.0 / 7.0 * std::numbers::pi / 2)));
  CHECK(grid.theta(7) - grid.theta(6) < 0.25 * (grid.theta(1) - grid.theta(0)));
  for (std::size_t i = 0; i < 8; ++i) CHECK(grid.theta_position(grid.theta(i)) == Catch::Approx(double(i)).margin(1e-9));
  CHECK(grid.theta_position(-0.1) == 0.0);
  CHECK(grid.theta_position(std::numbers::pi / 2) == 7.0);
  CHECK(ViewGrid{1, 1}.theta(0) == 0.1);
  CHECK(ViewGrid{1, 1}.theta_position(0.7) == 0.0);
  const Vector3 v = grid.direction(3 * 16 + 4);
  CHECK(v.z() == Catch::Approx(std::cos(grid.theta(3))));
  CHECK(std::atan2(v.y(), v.x()) == Catch::Approx(grid.phi(4)));
  CHECK(rotate_azimuth_to_zero(v, grid.phi(4)).y() == Catch::Approx(0.0).margin(1e-12));
}

TEST_CASE("stratified points cover the square evenly, and so does every residue class of them") {
  // Residue class t mod m is what texel t of a footprint of m texels draws: it must spread over the whole
  // square (radical-inverse points, for one, would give it a strip of azimuths 1/m wide).
  const std::size_t n = 128;
  const auto largest_gap = [](std::vector<double> values) {  // on the circle [0, 1)
    std::sort(values.begin(), values.end());
    double gap = values.front() + 1.0 - values.back();
    for (std::size_t i = 1; i < values.size(); ++i) gap = std::max(gap, values[i] - values[i - 1]);
    return gap;
  };
  for (std::size_t m : {1, 2, 4, 16, 32}) {
    for (std::size_t t = 0; t < m; ++t) {
      std::vector<double> first, second;
      for (std::size_t k = t; k < n; k += m) {
        const auto u = stratified_point(k, n, {0.3, 0.8});
        REQUIRE((u[0] >= 0.0 && u[0] < 1.0 && u[1] >= 0.0 && u[1] < 1.0));
        first.push_back(u[0]);
        second.push_back(u[1]);
      }
      const double points = double(first.size());
      CAPTURE(m, t);
      CHECK(largest_gap(first) == Catch::Approx(1.0 / points));
      CHECK(largest_gap(second) < 2.7 / points);
    }
  }
}

TEST_CASE("a base lobe is the MIP-0 LTC in the texel's frame, and its samples land around the reflection") {
  const Vector3 n = Vector3(0.3, -0.2, 1.0).normalized();
  const Vector3 v = Vector3(-0.5, 0.1, 0.8).normalized();
  const BaseLobeLtc specular({Component::specular, 0.01});
  const GgxLtcCurve curve(0.01);
  const LtcLookup lobe = specular.at(n, v);
  CHECK(lobe.matrix == curve.at(v.dot(n)).matrix);
  CHECK(lobe.amplitude == curve.at(v.dot(n)).amplitude);
  CHECK(specular.at(n, -v).matrix == curve.at(0.01).matrix);  // a view behind the micro-normal: grazing
  std::vector<Vector3> samples;
  for (std::size_t k = 0; k < 256; ++k)
    samples.push_back(sample_base_lobe(lobe, texel_frame(n, v), stratified_point(k, 256, {0.1, 0.2})));
  CHECK((mean_direction(samples) - (2 * v.dot(n) * n - v)).norm() < 0.02);
  for (const auto& l : samples) CHECK(l.norm() == Catch::Approx(1.0));
  const BaseLobeLtc diffuse({Component::diffuse, 0.01});
  CHECK(diffuse.at(n, v).matrix == pbrfit::Matrix3::Identity());
  CHECK(diffuse.at(n, v).amplitude == 1.0);
  double mean_cos = 0.0;
  for (std::size_t k = 0; k < 4096; ++k)
    mean_cos += sample_base_lobe(diffuse.at(n, v), texel_frame(n, v), stratified_point(k, 4096, {0.5, 0.5})).dot(n) / 4096.0;
  CHECK(mean_cos == Catch::Approx(2.0 / 3.0).margin(1e-3));
}

TEST_CASE("a footprint pools its texels' lobes: all of them, or a fixed subset, rotated to azimuth 0") {
  const NormalMap map = procedural_normal_map(NormalPattern::glitter, 32, 5);
  const EbrdfSampling sampling{{Component::specular, 0.01}, {4, 8}, 128, 9};
  const BaseLobeLtc base(sampling.lobe);
  const FootprintSampler sampler(map, sampling, base);
  CHECK(mip_levels(32) == 5);
  CHECK(mip_side(32, 5) == 1);

  const auto level1 = sampler.contributing_texels({1, 3, 2});
  CHECK(level1 == std::vector<std::size_t>{6 + 4 * 32, 7 + 4 * 32, 6 + 5 * 32, 7 + 5 * 32});
  const auto level5 = sampler.contributing_texels({5, 0, 0});
  CHECK(level5.size() == 128);
  CHECK(std::set<std::size_t>(level5.begin(), level5.end()).size() == 128);

  // Pooled sample k is texel k mod 4's lobe at stratified point k, azimuth-rotated.
  const std::size_t view = 2 * 8 + 3;
  const auto pooled = sampler.samples(level1, view);
  REQUIRE(pooled.size() == 128);
  const auto shift = sampler.shift(level1, view);
  const Vector3 v = sampling.views.direction(view);
  const Vector3& n = map.normals()[level1[1]];
  for (std::size_t k : {1, 5, 125}) {
    const Vector3 l = sample_base_lobe(base.at(n, v), texel_frame(n, v), stratified_point(k, 128, shift));
    CHECK((pooled[k] - rotate_azimuth_to_zero(l, sampling.views.phi(3))).norm() < 1e-15);
  }
  // Footprints and views have shifts of their own.
  CHECK(sampler.shift(level1, view) != sampler.shift(level1, view + 1));
  CHECK(sampler.shift(level1, view) != sampler.shift(sampler.contributing_texels({1, 3, 3}), view));
  CHECK(sampler.shift(level1, view) != sampler.shift(sampler.contributing_texels({2, 1, 1}), view));
}

TEST_CASE("on a flat map every level's eBRDF is the base lobe, with the lobe's albedo as amplitude") {
  const NormalMap map = flat_map(16);
  const EbrdfSampling sampling{{Component::specular, 0.02}, {4, 4}, 256, 2};
  const BaseLobeLtc base(sampling.lobe);
  const FootprintSampler sampler(map, sampling, base);
  for (std::size_t level : {1, 4}) {
    const std::size_t view = 2 * 4 + 1;
    const Vector3 v = sampling.views.direction(view);
    const auto samples = sampler.samples(sampler.contributing_texels({level, 0, 0}), view);
    const Vector3 mirror = rotate_azimuth_to_zero(Vector3(-v.x(), -v.y(), v.z()), sampling.views.phi(1));
    CHECK((mean_direction(samples) - mirror).norm() < 0.03);
    CHECK(sampler.amplitude({level, 0, 0}, view) == Catch::Approx(base.at(Vector3::UnitZ(), v).amplitude));
  }
  // The amplitude is the lobe's directional albedo (F = 1), as the split-sum DFG integrates it.
  for (double c : {1.0, 0.5, 0.1}) {
    const auto dfg = pbrfit::brdf::integrate_dfg(c, 0.02, pbrfit::brdf::SmithVisibility::height_correlated, {});
    CHECK(base.at(Vector3::UnitZ(), Vector3(std::sqrt(1 - c * c), 0, c)).amplitude ==
          Catch::Approx(dfg.scale + dfg.bias).margin(0.02));
  }
}
