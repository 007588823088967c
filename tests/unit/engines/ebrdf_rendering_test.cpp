#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <numbers>

#include "pbrfit/brdf/split_sum_dfg.hpp"
#include "pbrfit/ebrdf/ebrdf_fit.hpp"
#include "pbrfit/ebrdf/footprint_samples.hpp"
#include "pbrfit/ebrdf/ggx_ltc_curve.hpp"
#include "pbrfit/ebrdf/mip_tables.hpp"
#include "pbrfit/ebrdf/plane_renderer.hpp"
#include "pbrfit/ebrdf/plane_scene.hpp"

using namespace pbrfit::ebrdf;
using pbrfit::Matrix3;
using pbrfit::Vector3;

namespace {

// A level whose every entry holds diag(value, value, 1) and amplitude value.
LtcLevel constant_level(std::size_t side, const ViewGrid& views, float value) {
  LtcLevel level{side, {}, {}};
  for (std::size_t e = 0; e < side * side * views.count(); ++e) {
    for (int k = 0; k < 9; ++k) level.matrices.push_back(k == 0 || k == 4 ? value : (k == 8 ? 1.0f : 0.0f));
    level.amplitudes.push_back(value);
  }
  return level;
}

double mean_square_difference(const pbrfit::RgbImage& a, const pbrfit::RgbImage& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.values().size(); ++i) sum += std::pow(a.values()[i] - b.values()[i], 2);
  return sum / double(a.values().size());
}

}  // namespace

TEST_CASE("LTC mip lookups interpolate between levels, texels and views, wrapping u, v and phi") {
  const ViewGrid views{2, 4};
  LtcLevel fine = constant_level(2, views, 1.0f);
  fine.amplitudes[1 * views.count() + 0] = 3.0f;  // texel (u 1, v 0), view (theta 0, phi 0)
  const LtcMipTables tables(views, {fine, constant_level(1, views, 2.0f)});
  CHECK(tables.lookup(1.0, 0.25, 0.25, 0.0, 0.0).amplitude == Catch::Approx(1.0));
  CHECK(tables.lookup(1.0, 0.75, 0.25, 0.0, 0.0).amplitude == Catch::Approx(3.0));
  CHECK(tables.lookup(1.0, 1.75, -0.75, 0.0, 0.0).amplitude == Catch::Approx(3.0));   // the map tiles
  CHECK(tables.lookup(1.0, 0.5, 0.25, 0.0, 0.0).amplitude == Catch::Approx(2.0));     // between texels
  CHECK(tables.lookup(1.0, 0.75, 0.25, 0.0, std::numbers::pi / 4).amplitude == Catch::Approx(2.0));  // views
  CHECK(tables.lookup(1.0, 0.75, 0.25, 0.0, 7 * std::numbers::pi / 4).amplitude == Catch::Approx(2.0));  // wraps
  CHECK(tables.lookup(1.5, 0.25, 0.25, 1.0, 1.0).amplitude == Catch::Approx(1.5));  // between levels
  CHECK(tables.lookup(9.0, 0.1, 0.9, 1.0, 1.0).matrix(0, 0) == Catch::Approx(2.0));  // clamped to the coarsest
  CHECK_THROWS_AS(LtcMipTables(views, {constant_level(2, ViewGrid{1, 1}, 1.0f)}), std::invalid_argument);
  // The same lookup as the mip texels it blends: weights summing to 1, blended matrices equal to lookup()'s.
  for (const double level : {1.0, 1.5, 2.0})
    for (const LobeAxis axis : {LobeAxis::normal, LobeAxis::mirror}) {
      const LtcMipTables both(views, {fine, constant_level(1, views, 2.0f)}, axis);
      const auto lobes = both.texel_lobes(level, 0.6, 0.3, 0.7, 1.1);
      CHECK(lobes.size() == (level == 1.5 ? 8u : 4u));
      double weights = 0.0, amplitude = 0.0;
      Matrix3 blended = Matrix3::Zero();
      for (const auto& texel : lobes) {
        weights += texel.weight;
        amplitude += texel.weight * texel.lobe.amplitude;
        blended += texel.weight * texel.lobe.matrix;
      }
      const LtcLookup whole = both.lookup(level, 0.6, 0.3, 0.7, 1.1);
      CHECK(weights == Catch::Approx(1.0));
      CHECK(amplitude == Catch::Approx(whole.amplitude));
      CHECK((blended - whole.matrix).norm() < 1e-12);
    }
}

TEST_CASE("a specular lobe's matrices are interpolated in the mirror frame: a lobe that follows the mirror keeps its shape") {
  // Every view holds R(theta_i) S: the shape S turned to the view's mirror direction.
  const ViewGrid views{4, 2};
  const auto turn = [](double theta) {
    Matrix3 r;
    r << std::cos(theta), 0, -std::sin(theta), 0, 1, 0, std::sin(theta), 0, std::cos(theta);
    return r;
  };
  Matrix3 shape;
  shape << 0.2, 0.0, 0.05, 0.0, 0.3, 0.0, 0.0, 0.0, 1.0;
  LtcLevel level{1, {}, {}};
  for (std::size_t v = 0; v < views.count(); ++v) {
    const Matrix3 m = turn(views.theta(v / views.n_phi)) * shape;
    for (int k = 0; k < 9; ++k) level.matrices.push_back(float(m(k / 3, k % 3)));
    level.amplitudes.push_back(1.0f);
  }
  const LtcMipTables mirror(views, {level}, LobeAxis::mirror);
  const LtcMipTables normal(views, {level}, LobeAxis::normal);
  CHECK(mirror.lobe_axis() == LobeAxis::mirror);
  for (double theta : {0.0, 0.3, views.theta(2), 1.2, 1.5}) {
    CAPTURE(theta);
    const Matrix3 expected = turn(theta) * shape;
    CHECK((mirror.lookup(1.0, 0.3, 0.6, theta, 0.4).matrix - expected).norm() < 1e-6);
    const Vector3 axis = (mirror.lookup(1.0, 0.3, 0.6, theta, 0.4).matrix * Vector3::UnitZ()).normalized();
    CHECK(axis.dot(Vector3(-std::sin(theta), 0, std::cos(theta))) > 0.998);
  }
  // At a tabulated view both give the table's matrix; between views plain interpolation shrinks the lobe
  // towards the chord between the two mirror directions.
  CHECK((normal.lookup(1.0, 0.3, 0.6, views.theta(1), 0.0).matrix - turn(views.theta(1)) * shape).norm() < 1e-6);
  const double between = 0.5 * (views.theta(2) + views.theta(3));
  CHECK((normal.lookup(1.0, 0.3, 0.6, between, 0.0).matrix - turn(between) * shape).norm() > 1e-2);
}

TEST_CASE("the base GGX LTC has the lobe's albedo and concentrates around the mirror direction") {
  const double alpha = 0.09;
  const GgxLtcCurve curve(alpha, 8);
  for (double c : {1.0, 0.7, 0.3}) {
    const LtcLookup lobe = curve.at(c);
    const auto dfg = pbrfit::brdf::integrate_dfg(c, alpha, pbrfit::brdf::SmithVisibility::height_correlated, {});
    CHECK(lobe.amplitude == Catch::Approx(dfg.scale + dfg.bias).margin(0.02));
    const Vector3 axis = (lobe.matrix * Vector3::UnitZ()).normalized();
    CHECK(axis.x() < 0.05);  // towards the mirror side of a view at azimuth 0
  }
}

TEST_CASE("on a flat map the ground truth, naive and prefiltered renders agree, and show the light") {
  const NormalMap flat(8, std::vector<Vector3>(64, Vector3::UnitZ()));
  const GgxLtcCurve curve(0.01, 16);
  // Prefiltered tables of a flat map: every footprint's lobe is the base lobe itself, so take the curve's LTC
  // at each tabulated elevation.
  const ViewGrid views{8, 4};
  std::vector<LtcLevel> levels;
  for (std::size_t side = 4; side >= 1; side /= 2) {
    LtcLevel level{side, {}, {}};
    for (std::size_t t = 0; t < side * side; ++t)
      for (std::size_t v = 0; v < views.count(); ++v) {
        const LtcLookup lobe = curve.at(std::cos(views.theta(v / views.n_phi)));
        for (int k = 0; k < 9; ++k) level.matrices.push_back(float(lobe.matrix(k / 3, k % 3)));
        level.amplitudes.push_back(float(lobe.amplitude));
      }
    levels.push_back(std::move(level));
  }
  const LtcMipTables specular(views, levels, LobeAxis::mirror);
  for (auto& level : levels) std::fill(level.amplitudes.begin(), level.amplitudes.end(), 1.0f);
  for (auto& level : levels)
    for (std::size_t e = 0; e < level.amplitudes.size(); ++e)
      for (int k = 0; k < 9; ++k) level.matrices[9 * e + std::size_t(k)] = k % 4 == 0 ? 1.0f : 0.0f;
  const LtcMipTables diffuse(views, levels);
  const RenderInputs inputs{&flat, &curve, &specular, &diffuse, {}};
  for (const SceneView view : {SceneView::top, SceneView::grazing}) {
    const PlaneScene scene = make_plane_scene(view, 8.0, 24);
    CHECK(centre_texels_per_pixel(scene, 8) > 0.2);
    const auto truth = render_plane(scene, RenderMethod::ground_truth, inputs);
    const auto naive = render_plane(scene, RenderMethod::naive, inputs);
    const auto ours = render_plane(scene, RenderMethod::ours, inputs);
    float brightest = 0.0f;
    for (float v : truth.values()) brightest = std::max(brightest, v);
    CAPTURE(scene_view_name(view));
    CHECK(brightest > 0.5f);
    CHECK(mean_square_difference(truth, naive) < 5e-3);
    CHECK(mean_square_difference(truth, ours) < 2e-2);
  }
}

TEST_CASE("prefiltered from a flat map, the tables give back the base lobe: ours renders what MIP-0 shading does") {
  // The whole pipeline (pooled base lobes, fits, mip lookups) on a map whose every footprint is flat.
  const std::size_t size = 8;
  const NormalMap flat(size, std::vector<Vector3>(size * size, Vector3::UnitZ()));
  const GgxLtcCurve curve(0.01);
  const auto prefilter = [&](Component component, ViewGrid views) {
    const EbrdfSampling sampling{{component, 0.01}, views, 128, 3};
    const BaseLobeLtc base(sampling.lobe);
    const FootprintSampler sampler(flat, sampling, base);
    std::vector<LtcLevel> levels;
    for (std::size_t level = 1; level <= mip_levels(size); ++level) {
      LtcLevel table{mip_side(size, level), {}, {}};
      for (std::size_t y = 0; y < table.side; ++y)
        for (std::size_t x = 0; x < table.side; ++x)
          for (std::size_t v = 0; v < views.count(); ++v) {
            pbrfit::RandomStream unused(0, 0);
            const MipTexel texel{level, x, y};
            const auto fit = fit_ebrdf(sampler.samples(sampler.contributing_texels(texel), v),
                                       sampler.amplitude(texel, v), {}, unused);
            for (double m : fit.matrix) table.matrices.push_back(float(m));
            table.amplitudes.push_back(float(fit.amplitude));
          }
      levels.push_back(std::move(table));
    }
    return LtcMipTables(views, std::move(levels),
                        component == Component::specular ? LobeAxis::mirror : LobeAxis::normal);
  };
  const LtcMipTables specular = prefilter(Component::specular, {8, 2});
  const LtcMipTables diffuse = prefilter(Component::diffuse, {2, 2});
  const RenderInputs inputs{&flat, &curve, &specular, &diffuse, {}};
  for (const SceneView view : {SceneView::top, SceneView::grazing}) {
    const PlaneScene scene = make_plane_scene(view, 16.0, 32);
    CHECK(centre_texels_per_pixel(scene, size) > 2.0);  // the tables, not MIP-0 shading, at the centre
    const auto truth = render_plane(scene, RenderMethod::ground_truth, inputs);
    const auto ours = render_plane(scene, RenderMethod::ours, inputs);
    double energy_truth = 0.0, energy_ours = 0.0;
    for (std::size_t i = 0; i < truth.values().size(); ++i) {
      energy_truth += truth.values()[i];
      energy_ours += ours.values()[i];
    }
    CAPTURE(scene_view_name(view), mean_square_difference(truth, ours), energy_ours / energy_truth);
    CHECK(energy_ours == Catch::Approx(energy_truth).epsilon(view == SceneView::top ? 0.002 : 0.01));
    CHECK(mean_square_difference(truth, ours) < (view == SceneView::top ? 1.5e-4 : 1e-3));
  }
}
