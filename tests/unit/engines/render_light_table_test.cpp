// The light weight table of genBRDF's metric: built from the sphere's samples, pruned, and the metric
// over the kept cells; pruning must not change how candidate BRDFs rank against a reference.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_floating_point.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "pbrfit/brdf/ggx.hpp"
#include "pbrfit/render/light_metric.hpp"
#include "pbrfit/render/procedural_environments.hpp"
#include "pbrfit/render/sphere_renderer.hpp"

using namespace pbrfit::render;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using pbrfit::RgbImage;
using pbrfit::brdf::merl_cells;
using pbrfit::Vector3;

namespace {

constexpr double pi = std::numbers::pi;

const SphereSamples& room_samples() {
  static const SphereSamples samples(procedural_interior(), SphereView(48), 64);
  return samples;
}

const LightWeightTable& room_table() {
  static const LightWeightTable table(room_samples());
  return table;
}

// Diffuse plus a specular lobe of the half-vector cosine, both coloured; 0 below either horizon.
BrdfFunction lobe_brdf(Rgb diffuse, Rgb specular, std::function<double(const Vector3&, const Vector3&)> lobe) {
  return [=](const Vector3& wi, const Vector3& wo) {
    if (wi.z() <= 0.0 || wo.z() <= 0.0) return Rgb{0.0, 0.0, 0.0};
    const double s = lobe(wi, wo);
    return Rgb{diffuse[0] / pi + specular[0] * s, diffuse[1] / pi + specular[1] * s, diffuse[2] / pi + specular[2] * s};
  };
}

BrdfFunction ggx(double alpha, Rgb diffuse = {0.05, 0.1, 0.2}, Rgb specular = {0.9, 0.7, 0.5}) {
  return lobe_brdf(diffuse, specular, [alpha](const Vector3& wi, const Vector3& wo) {
    const Vector3 h = (wi + wo).normalized();
    return pbrfit::brdf::ggx_distribution(alpha, h.z()) *
           pbrfit::brdf::smith_visibility(pbrfit::brdf::SmithVisibility::height_correlated, alpha, wo.z(), wi.z());
  });
}

BrdfFunction blinn_phong(double exponent) {
  return lobe_brdf({0.05, 0.1, 0.2}, {0.9, 0.7, 0.5}, [exponent](const Vector3& wi, const Vector3& wo) {
    return (exponent + 2.0) / (2.0 * pi) * std::pow((wi + wo).normalized().z(), exponent);
  });
}

double channel_sum(const Rgb& c) { return c[0] + c[1] + c[2]; }

// Candidate indices ordered by their metric against the reference over `table`'s cells, with the metrics.
std::pair<std::vector<std::size_t>, std::vector<double>> ranking(const PrunedLightTable& table,
                                                                 const BrdfFunction& reference,
                                                                 const std::vector<BrdfFunction>& candidates) {
  const std::vector<double> measured = kept_values(table, reference);
  std::vector<double> metric;
  for (const BrdfFunction& c : candidates) metric.push_back(channel_sum(light_metric(table, measured, kept_values(table, c))));
  std::vector<std::size_t> order(candidates.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return metric[a] < metric[b]; });
  return {order, metric};
}

}  // namespace

TEST_CASE("the light weight table holds the unit-BRDF render, cell by cell") {
  const LightWeightTable& table = room_table();
  const RgbImage unit = render_sphere(room_samples(), [](const Vector3&, const Vector3&) { return Rgb{1.0, 1.0, 1.0}; });
  pbrfit::brdf::MerlTable by_cell;
  for (std::size_t k = 0; k < 3; ++k)
    for (std::size_t c = 0; c < merl_cells; ++c) by_cell.set(k, c, double(c % 7) + 0.5 * double(k));
  const RgbImage tabulated = render_sphere(room_samples(), by_cell);
  for (std::size_t k = 0; k < 3; ++k) {
    double pixels = 0.0, tabulated_pixels = 0.0, cells = 0.0;
    for (std::size_t p = 0; p < unit.pixels(); ++p) {
      pixels += unit.pixel(p)[k];
      tabulated_pixels += tabulated.pixel(p)[k];
    }
    for (std::size_t c = 0; c < merl_cells; ++c) cells += table.weight(k, c) * by_cell.value(k, c);
    CHECK_THAT(table.total()[k], WithinRel(pixels, 1e-5));
    CHECK_THAT(cells, WithinRel(tabulated_pixels, 1e-5));
  }
  CHECK(table.lit_cells() > 10'000);
  CHECK(std::all_of(table.values().begin(), table.values().end(), [](double w) { return w >= 0.0; }));
}

TEST_CASE("a light weight table built from the sampling loop by pixel ranges matches the stored samples'") {
  const EnvironmentMap room = procedural_interior();
  const SphereView view(48);
  LightWeightTable direct(room, view, 64, {0, 1000});
  direct += LightWeightTable(room, view, 64, {1000, view.pixels()});
  const LightWeightTable& stored = room_table();
  for (std::size_t k = 0; k < 3; ++k) CHECK_THAT(direct.total()[k], WithinRel(stored.total()[k], 1e-6));
  std::size_t differ = 0;
  for (std::size_t i = 0; i < stored.values().size(); ++i)
    differ += std::abs(direct.values()[i] - stored.values()[i]) > 1e-6 * (stored.values()[i] + 1e-3);
  CHECK(differ == 0);  // stored cells come from the directions before rounding; only weights are rounded
  CHECK(LightWeightTable().lit_cells() == 0);
}

TEST_CASE("pruning keeps the heaviest cells up to the kept share and reports what it drops") {
  const LightWeightTable& table = room_table();
  const PrunedLightTable pruned(table);
  const PrunedLightTable all(table, 1.0);
  CHECK(all.size() == table.lit_cells());
  CHECK(all.dropped_share() == Rgb{0.0, 0.0, 0.0});
  CHECK(pruned.size() < all.size());
  CHECK(std::is_sorted(pruned.cells().begin(), pruned.cells().end()));
  for (std::size_t k = 0; k < 3; ++k) {
    double kept = 0.0;
    for (std::size_t i = 0; i < pruned.size(); ++i) {
      kept += pruned.weight(k, i);
      REQUIRE(pruned.weight(k, i) == table.weight(k, pruned.cells()[i]));
      REQUIRE(pruned.squared_weights()[k * pruned.size() + i] == pruned.weight(k, i) * pruned.weight(k, i));
    }
    CHECK(kept >= default_keep_share * table.total()[k]);
    CHECK(pruned.dropped_share()[k] <= 1.0 - default_keep_share);
    CHECK(pruned.dropped_share()[k] > 0.0);
    CHECK_THAT(pruned.dropped_share()[k] + kept / table.total()[k], WithinAbs(1.0, 1e-12));
  }
  CHECK(PrunedLightTable(table, 0.5).size() < pruned.size());
  CHECK_THROWS_AS(PrunedLightTable(table, 0.0), std::invalid_argument);
  CHECK_THROWS_AS(PrunedLightTable(table, 1.5), std::invalid_argument);
}

TEST_CASE("each kept cell's representative directions lie in that cell") {
  const PrunedLightTable pruned(room_table());
  const auto pairs = representative_pairs(pruned);
  REQUIRE(pairs.size() == pruned.size());
  for (std::size_t i = 0; i < pairs.size(); i += 97)
    CHECK(pbrfit::brdf::merl_cell_of(pbrfit::brdf::to_half_diff(pairs[i].wi, pairs[i].wo)).flat() == pruned.cells()[i]);
}

TEST_CASE("the metric: 0 for equal BRDFs, sum of T^2 f^2 for f against 2f, missing cells skipped") {
  const PrunedLightTable pruned(room_table());
  const std::size_t n = pruned.size();
  const std::vector<double> f = kept_values(pruned, ggx(0.2));
  std::vector<double> twice = f;
  for (double& v : twice) v *= 2.0;
  CHECK(light_metric(pruned, f, f) == Rgb{0.0, 0.0, 0.0});
  std::vector<double> measured = f;
  measured[5] = measured[n + 5] = measured[2 * n + 5] = std::nan("");
  const Rgb with_gap = light_metric(pruned, measured, twice);
  const Rgb metric = light_metric(pruned, f, twice);
  for (std::size_t k = 0; k < 3; ++k) {
    double expected = 0.0;
    for (std::size_t i = 0; i < n; ++i) expected += pruned.weight(k, i) * pruned.weight(k, i) * f[k * n + i] * f[k * n + i];
    CHECK_THAT(metric[k], WithinRel(expected, 1e-12));
    const double t = pruned.weight(k, 5) * f[k * n + 5];
    CHECK_THAT(with_gap[k], WithinRel(expected - t * t, 1e-12));
  }
  std::vector<double> broken = f;
  broken[n + 3] = std::nan("");
  CHECK(std::isnan(light_metric(pruned, f, broken)[1]));
  CHECK(!std::isnan(light_metric(pruned, f, broken)[0]));
  CHECK_THROWS_AS(light_metric(pruned, f, std::vector<double>(n)), std::invalid_argument);
  pbrfit::brdf::MerlTable table;
  table.set(2, pruned.cells()[1], 0.25);
  CHECK(kept_values(pruned, table)[2 * n + 1] == 0.25);
}

TEST_CASE("pruning does not change how candidate BRDFs rank against a reference") {
  const std::vector<BrdfFunction> candidates = {
      lobe_brdf({0.3, 0.3, 0.3}, {0.0, 0.0, 0.0}, [](const Vector3&, const Vector3&) { return 0.0; }),
      ggx(0.05), ggx(0.1), ggx(0.12), ggx(0.2), ggx(0.3), ggx(0.5), ggx(0.15, {0.1, 0.1, 0.1}),
      ggx(0.15, {0.05, 0.1, 0.2}, {0.7, 0.7, 0.7}), blinn_phong(20.0), blinn_phong(100.0), blinn_phong(400.0)};
  const BrdfFunction reference = ggx(0.15);
  const auto [full_order, full] = ranking(PrunedLightTable(room_table(), 1.0), reference, candidates);
  const auto [pruned_order, pruned] = ranking(PrunedLightTable(room_table()), reference, candidates);
  CHECK(pruned_order == full_order);
  for (std::size_t c = 0; c < candidates.size(); ++c) CHECK_THAT(pruned[c], WithinRel(full[c], 1e-4));
}
