// The precomputation and the fast metric of genBRDF (render/), on one core: SphereSamples of the
// procedural interior, the light weight table and its pruning, then how many kept cells per second the
// metric accumulates for a candidate given as per-cell values (what a search does after evaluating the
// candidate at the kept cells). For context also: a full render of a BRDF callable and of a MERL table
// from the stored samples, and evaluating a callable at the kept cells' representative directions.
//   bench_render_metric [resolution=128] [samples_per_pixel=256] [keep_share=0.9999]
// Not a test; figures go to docs/BENCHMARKS.md.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <vector>

#include "pbrfit/brdf/ggx.hpp"
#include "pbrfit/render/light_metric.hpp"
#include "pbrfit/render/procedural_environments.hpp"
#include "pbrfit/render/sphere_renderer.hpp"

using namespace pbrfit::render;
using Clock = std::chrono::steady_clock;
using pbrfit::Vector3;

namespace {

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

BrdfFunction ggx(double alpha) {
  return [alpha](const Vector3& wi, const Vector3& wo) {
    if (wi.z() <= 0.0 || wo.z() <= 0.0) return Rgb{0.0, 0.0, 0.0};
    const double s = pbrfit::brdf::ggx_distribution(alpha, (wi + wo).normalized().z()) *
                     pbrfit::brdf::smith_visibility(pbrfit::brdf::SmithVisibility::height_correlated, alpha, wo.z(), wi.z());
    return Rgb{0.05 / std::numbers::pi + 0.9 * s, 0.1 / std::numbers::pi + 0.7 * s, 0.2 / std::numbers::pi + 0.5 * s};
  };
}

// Kept cells per second of the metric alone, best of 5 passes of at least 0.2 s each.
double metric_rate(const PrunedLightTable& table, const std::vector<double>& measured,
                   const std::vector<double>& candidate, double& checksum) {
  double best = 0.0;
  for (int pass = 0; pass < 5; ++pass) {
    std::size_t evaluations = 0;
    const auto start = Clock::now();
    do {
      checksum += light_metric(table, measured, candidate)[1];
      ++evaluations;
    } while (seconds_since(start) < 0.2);
    best = std::max(best, double(evaluations * table.size()) / seconds_since(start));
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t resolution = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 128;
  const std::size_t samples_per_pixel = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 256;
  const double keep_share = argc > 3 ? std::strtod(argv[3], nullptr) : default_keep_share;

  auto start = Clock::now();
  const EnvironmentMap environment = procedural_interior();
  const double environment_seconds = seconds_since(start);
  start = Clock::now();
  const SphereSamples samples(environment, SphereView(resolution), samples_per_pixel);
  const double samples_seconds = seconds_since(start);
  start = Clock::now();
  const LightWeightTable table(samples);
  const double table_seconds = seconds_since(start);
  start = Clock::now();
  const PrunedLightTable pruned(table, keep_share);
  const double prune_seconds = seconds_since(start);

  std::printf("scene: procedural_interior, %zu x %zu pixels, %zu samples per pixel\n", resolution, resolution,
              samples_per_pixel);
  std::printf("environment map       %8.3f s\n", environment_seconds);
  std::printf("SphereSamples         %8.3f s  (%zu stored samples above the horizon, %.1f MB)\n", samples_seconds,
              samples.size(), double(samples.size()) * 28.0 / 1e6);
  std::printf("light weight table    %8.3f s  (%zu lit cells of %zu)\n", table_seconds, table.lit_cells(),
              pbrfit::brdf::merl_cells);
  std::printf("pruning               %8.3f s  (keep share %.6g: %zu kept cells, dropped share %.3g / %.3g / %.3g)\n",
              prune_seconds, keep_share, pruned.size(), pruned.dropped_share()[0], pruned.dropped_share()[1],
              pruned.dropped_share()[2]);

  start = Clock::now();
  const std::vector<double> measured = kept_values(pruned, ggx(0.15));
  const std::vector<double> candidate = kept_values(pruned, ggx(0.3));
  const double values_seconds = seconds_since(start) / 2.0;
  double checksum = 0.0;
  const double rate = metric_rate(pruned, measured, candidate, checksum);
  std::printf("metric accumulation   %8.3g kept cells/s on one core (3 channels each; %.3g s per evaluation)\n", rate,
              double(pruned.size()) / rate);
  std::printf("callable at the kept cells' representative directions (std::function, scalar GGX): %.3g cells/s\n",
              double(pruned.size()) / values_seconds);

  start = Clock::now();
  const pbrfit::RgbImage image = render_sphere(samples, ggx(0.15));
  const double render_seconds = seconds_since(start);
  pbrfit::brdf::MerlTable merl;
  start = Clock::now();
  const pbrfit::RgbImage tabulated = render_sphere(samples, merl);
  const double merl_seconds = seconds_since(start);
  std::printf("render of a callable  %8.3f s  (%.3g samples/s)\n", render_seconds, double(samples.size()) / render_seconds);
  std::printf("render of a MERL table%8.3f s  (%.3g samples/s)\n", merl_seconds, double(samples.size()) / merl_seconds);
  std::printf("(checksum %.6g %.6g %.6g)\n", checksum, double(image.values()[3 * (resolution * resolution / 2)]),
              double(tabulated.values()[0]));
  return 0;
}
