// The genBRDF search's inner loop on one core (issue 10, goal 1): the metric of a candidate BRDF over the
// kept cells of the pruned light weight table, evaluated by the batch interpreter for the training
// materials of the metal class. Reports, for Cook-Torrance (the seed, a typical candidate): kept cells,
// cells per second of one metric evaluation with and without the fixed part folded out
// (gp/fixed_part.hpp), the time to score one candidate (12 Nelder-Mead fits), and what that implies for a
// search of 100 generations x 4 islands x 256 genomes on 2 cores.
// Then the Cook-Torrance fits with that effort, with it but no warm starts (each fit's first search from
// the previous fit's point), and with 32 starts x 1000 evaluations (how far the search's fits are from
// converged), each also averaged over 8 random streams. Defaults: the search scene and fit of jobs/merl-metals.yaml.
//   bench_brdf_metric [resolution=48] [samples_per_pixel=4] [keep_share=0.999] [starts=4] [evaluations=100]
// Not a test; figures go to docs/BENCHMARKS.md.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <algorithm>

#include "pbrfit/gp/batch_interpreter.hpp"
#include "pbrfit/gp/expression_parser.hpp"
#include "pbrfit/gp/fixed_part.hpp"
#include "pbrfit/jobs/brdf/brdf_inputs.hpp"
#include "pbrfit/jobs/brdf/candidate_score.hpp"
#include "pbrfit/jobs/brdf/material_sets.hpp"
#include "pbrfit/jobs/brdf/material_source.hpp"
#include "pbrfit/jobs/brdf/seed_brdfs.hpp"
#include "pbrfit/render/light_weight_table.hpp"
#include "pbrfit/render/procedural_environments.hpp"

using namespace pbrfit;
using namespace pbrfit::jobs::brdf;
using Clock = std::chrono::steady_clock;

namespace {

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Metric evaluations per second of `program` on `data`, best of 3 passes of at least 0.3 s.
double evaluations_per_second(const gp::Program& program, const gp::Dataset& data, double& checksum) {
  gp::BatchInterpreter<float> interpreter(data);
  double best = 0.0;
  for (int pass = 0; pass < 3; ++pass) {
    std::size_t n = 0;
    const auto start = Clock::now();
    do {
      checksum += interpreter.error(program);
      ++n;
    } while (seconds_since(start) < 0.3);
    best = std::max(best, double(n) / seconds_since(start));
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t resolution = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 48;
  const std::size_t spp = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 4;
  const double keep_share = argc > 3 ? std::strtod(argv[3], nullptr) : 0.999;
  const gp::ParameterFitOptions fit{argc > 4 ? std::strtoul(argv[4], nullptr, 10) : 4,
                                    argc > 5 ? std::strtoul(argv[5], nullptr, 10) : 100};
  auto start = Clock::now();
  const render::SphereSamples samples(render::procedural_interior(), render::SphereView(resolution), spp);
  const render::LightWeightTable weights(samples);
  const render::PrunedLightTable table(weights, keep_share);
  std::printf("scene: procedural interior, %zu x %zu pixels, %zu samples per pixel: %.2f s\n", resolution, resolution,
              spp, seconds_since(start));
  std::printf("cells: %zu lit, %zu kept at keep_share %.6g (dropped %.3g %.3g %.3g)\n", weights.lit_cells(), table.size(),
              keep_share, table.dropped_share()[0], table.dropped_share()[1], table.dropped_share()[2]);
  start = Clock::now();
  const auto names = material_set("metals")->training;
  std::vector<brdf::MerlTable> materials;
  for (const auto& name : names) materials.push_back(load_material(name, MaterialSource{"", "", "results/merl-cache"}));
  const MetricData data(table, materials, names);
  std::printf("4 training metals loaded and their datasets built: %.2f s (%zu rows for steel, red)\n", seconds_since(start),
              data.channel(0, 0).data.rows());

  const auto parsed = std::get<gp::ParsedExpression>(
      gp::parse_expression(find_seed("cook_torrance")->expression, {pbrfit::brdf::direction_input_names(), brdf_parameter_names()}));
  const auto compiled = *gp::compile(gp::tree_of(parsed.program, parsed.parameter_slots), brdf_parameter_count);
  const auto& steel = data.channel(0, 0).data;
  const auto folded = gp::fold_fixed_part(compiled.program, compiled.parameter_slots, steel);
  double checksum = 0.0;
  const double plain = evaluations_per_second(compiled.program, steel, checksum) * double(steel.rows());
  const double fast = evaluations_per_second(folded.program, folded.dataset, checksum) * double(steel.rows());
  std::printf("Cook-Torrance: %u instructions, %u after folding (%zu fixed columns)\n", unsigned(compiled.program.length),
              unsigned(folded.program.length), folded.dataset.input_count() - steel.input_count());
  std::printf("metric evaluation on one core: %.3g cells/s as compiled, %.3g cells/s folded\n", plain, fast);

  start = Clock::now();
  std::size_t scored = 0, evaluations = 0;
  do {
    evaluations += score_candidate(compiled, data, fit, RandomStream(1, 0, scored, 0)).evaluations;
    ++scored;
  } while (seconds_since(start) < 3.0);
  const double per_candidate = seconds_since(start) / double(scored);
  std::printf("one candidate scored (12 fits, %zu starts x %zu evaluations): %.3f s, %.0f evaluations; "
              "%.3g cells/s overall\n", fit.starts, fit.evaluations_per_start, per_candidate,
              double(evaluations) / double(scored), double(evaluations) / double(scored) * double(steel.rows()) / per_candidate);
  std::printf("a search of 102400 candidates on 2 cores would take %.1f h (before duplicates are skipped)\n",
              102400.0 * per_candidate / 2.0 / 3600.0);
  std::printf("Cook-Torrance fits to the training metals (metric S' per channel, parameters p0..p3):\n");
  gp::ParameterFitOptions cold = fit;
  cold.warm_start = false;
  for (const auto& [label, effort] : {std::pair{"search's effort", fit}, std::pair{"search's effort, no warm starts", cold},
                                      std::pair{"32 starts x 1000", gp::ParameterFitOptions{32, 1000}}}) {
    const auto score = score_candidate(compiled, data, effort, RandomStream(1, 0, 0, 0));
    double mean = 0.0, worst = 0.0;
    for (std::uint64_t seed = 0; seed < 8; ++seed) {
      const double e = seed == 0 ? score.error : score_candidate(compiled, data, effort, RandomStream(1, 0, seed, 0)).error;
      mean += e / 8.0;
      worst = std::max(worst, e);
    }
    std::printf("  %s: total %.4g (over 8 random streams: mean %.4g, worst %.4g)\n", label, score.error, mean, worst);
    for (std::size_t m = 0; m < data.materials(); ++m)
      for (std::size_t c = 0; c < 3; ++c) {
        const auto& p = score.parameters[3 * m + c];
        std::printf("    %-22s %c  %9.4g %9.4g %9.4g %9.4g\n", data.name(m).c_str(), "rgb"[c], p[0], p[1], p[2], p[3]);
      }
  }
  std::printf("(checksum %.6g)\n", checksum);
  return 0;
}
