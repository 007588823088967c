// The eBRDF fitter against the thesis' SGD baseline (docs/BENCHMARKS.md, issue 11 goal 2): on each built-in
// 128 x 128 map at the thesis' settings (GGX roughness 0.1, 8 x 16 specular views, 128 samples), for every
// mip level, a fixed pseudo-random set of (texel, view) effective BRDFs is fitted by `descent` (the default)
// and by `sgd`, both judged by the same 32-axis sliced Wasserstein error. Prints per level the mean errors,
// the share of fits where descent's error is at most SGD's, and the time per fit.
// Usage: bench_ebrdf_fit [fits per level = 64] [descent iterations] [descent axes] (default: the job defaults)
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "pbrfit/ebrdf/ebrdf_fit.hpp"
#include "pbrfit/ebrdf/footprint_samples.hpp"
#include "pbrfit/ebrdf/procedural_normal_maps.hpp"

using namespace pbrfit::ebrdf;

namespace {

struct Tally {
  double descent_error = 0, sgd_error = 0, descent_seconds = 0, sgd_seconds = 0;
  int fits = 0, descent_not_worse = 0;

  void add(const Tally& t) {
    descent_error += t.descent_error, sgd_error += t.sgd_error;
    descent_seconds += t.descent_seconds, sgd_seconds += t.sgd_seconds;
    fits += t.fits, descent_not_worse += t.descent_not_worse;
  }
  void print(const char* map, const char* level) const {
    std::printf("| %s | %s | %d | %.4f | %.4f | %.1f %% | %.2f | %.2f |\n", map, level, fits, descent_error / fits,
                sgd_error / fits, 100.0 * descent_not_worse / fits, 1e3 * descent_seconds / fits,
                1e3 * sgd_seconds / fits);
  }
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Tally fit_level(const FootprintSampler& sampler, std::size_t level, int count, const EbrdfFitSettings& descent) {
  const std::size_t side = mip_side(128, level);
  const std::size_t views = sampler.sampling().views.count();
  pbrfit::RandomStream pick(5, level);
  EbrdfFitSettings sgd;
  sgd.method = FitMethod::sgd;
  Tally t;
  for (int k = 0; k < count; ++k) {
    const MipTexel texel{level, std::size_t(pick.below(side)), std::size_t(pick.below(side))};
    const std::size_t view = pick.below(views);
    const auto samples = sampler.samples(sampler.contributing_texels(texel), view);
    const double amplitude = sampler.amplitude(texel, view);
    pbrfit::RandomStream random(7, level, std::uint64_t(k));
    auto start = std::chrono::steady_clock::now();
    const EbrdfFit ours = fit_ebrdf(samples, amplitude, descent, random);
    t.descent_seconds += seconds_since(start);
    start = std::chrono::steady_clock::now();
    const EbrdfFit baseline = fit_ebrdf(samples, amplitude, sgd, random);
    t.sgd_seconds += seconds_since(start);
    t.descent_error += ours.error, t.sgd_error += baseline.error;
    t.descent_not_worse += ours.error <= baseline.error;
    ++t.fits;
  }
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  const int count = argc > 1 ? std::atoi(argv[1]) : 64;
  EbrdfFitSettings descent;
  if (argc > 2) descent.descent.iterations = std::size_t(std::atoi(argv[2]));
  if (argc > 3) descent.descent.axes = std::size_t(std::atoi(argv[3]));
  std::printf("descent: %zu iterations, %zu axes\n\n", descent.descent.iterations, descent.descent.axes);
  std::printf("| map | level | fits | descent error | SGD error | descent <= SGD | descent ms/fit | SGD ms/fit |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  Tally all;
  for (const auto& name : normal_pattern_names()) {
    const NormalMap map = procedural_normal_map(normal_pattern_from(name), 128, 1);
    const EbrdfSampling sampling{{Component::specular, 0.01}, {8, 16}, 128, 1};
    const BaseLobeLtc base(sampling.lobe);
    const FootprintSampler sampler(map, sampling, base);
    Tally per_map;
    for (std::size_t level = 1; level <= 7; ++level) {
      const Tally t = fit_level(sampler, level, count, descent);
      t.print(name.c_str(), std::to_string(level).c_str());
      per_map.add(t);
    }
    per_map.print(name.c_str(), "all");
    all.add(per_map);
  }
  all.print("all", "all");
}
