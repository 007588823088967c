#include "pbrfit/jobs/sweep/problem_catalogue.hpp"

#include <limits>
#include <stdexcept>

#include "pbrfit/core/error.hpp"
#include "pbrfit/jobs/sweep/multi_lobe_sg_problem.hpp"
#include "pbrfit/jobs/sweep/parallax_problem.hpp"
#include "pbrfit/jobs/sweep/sphere_light_problem.hpp"

namespace pbrfit::jobs::sweep {
namespace {

std::unique_ptr<SweepProblem> make_sphere_light(const SweepKeys& sweep) {
  const ObjectiveKeys& objective = sweep.objective;
  SphereLightSettings settings;
  settings.norm_p = objective.norm.value;
  settings.view_panels = int(objective.views.value_or(std::size_t(settings.view_panels)));
  settings.truth = integration(objective, 1e-4);
  return make_sphere_light_problem(settings);
}

std::unique_ptr<SweepProblem> make_multi_lobe_sg(const SweepKeys& sweep) {
  MultiLobeSgSettings settings;
  settings.lobes = sweep.objective.lobes.value_or(settings.lobes);
  settings.samples_per_strategy = sweep.objective.samples.value_or(settings.samples_per_strategy);
  return make_multi_lobe_sg_problem(settings);
}

std::unique_ptr<SweepProblem> make_parallax(const SweepKeys& sweep, ParallaxStudy study) {
  const ObjectiveKeys& objective = sweep.objective;
  ParallaxSettings settings;
  settings.study = study;
  settings.window = objective.window.value_or(settings.window);
  settings.distance = objective.distance.value_or(settings.distance);
  settings.integration = integration(objective, 1e-5);
  settings.coarse_tolerance = coarse_tolerance(objective, settings.integration.abs_tolerance, 1e-3);
  return make_parallax_problem(settings);
}

}  // namespace

const std::vector<ProblemEntry>& problem_catalogue() {
  static const std::vector<ProblemEntry> entries = {
      {"ltc_ggx", "isotropic LTC table of GGX (Heitz et al. 2016) on the published grid, beside the published table",
       {"samples", "judge_samples", "polygon_quads", "polygon_tolerance", "fit_to", "training_quads", "render_size"}, make_ltc_ggx},
      {"ltc", "isotropic LTC tables of the built-in BRDF families, a BRDF expression or a measured material",
       {"samples", "judge_samples", "polygon_quads", "polygon_tolerance", "fit_to", "training_quads", "render_size"}, make_ltc},
      {"sphere_light", "GGX lit by a spherical light: roughness modification, capped, representative point models",
       {"norm", "tolerance", "max_evaluations", "views"}, make_sphere_light},
      {"multi_lobe_sg", "multi-lobe spherical Gaussian kernel for GGX environment lighting", {"samples", "lobes"},
       make_multi_lobe_sg},
      {"parallax_distance", "parallax-corrected probes: roughness of a perpendicular lobe over roughness x distance",
       {"tolerance", "coarse_tolerance", "max_evaluations", "window"},
       [](const SweepKeys& sweep) { return make_parallax(sweep, ParallaxStudy::distance); }},
      {"parallax_angle", "parallax-corrected probes: roughness and shift of a perpendicular lobe over roughness x angle",
       {"tolerance", "coarse_tolerance", "max_evaluations", "window", "distance"},
       [](const SweepKeys& sweep) { return make_parallax(sweep, ParallaxStudy::angle); }},
      {"expression", "any model stated as an expression, fitted to a target expression over a domain",
       {"norm", "integrator", "samples", "tolerance", "coarse_tolerance", "max_evaluations"}, make_expression},
  };
  return entries;
}

std::vector<std::string> problem_names() {
  std::vector<std::string> names;
  for (const auto& entry : problem_catalogue()) names.push_back(entry.name);
  return names;
}

const ProblemEntry& find_problem(const std::string& name) {
  for (const auto& entry : problem_catalogue())
    if (entry.name == name) return entry;
  throw std::logic_error("sweep: unknown problem " + name);
}

spec::Keys<ObjectiveKeys> objective_keys() {
  using O = ObjectiveKeys;
  spec::Keys<O> k("objective");
  k.integer("samples", "points per sampling strategy of the objective's quasi-Monte Carlo estimate", &O::samples)
      .range(16, 1 << 22);
  k.integer("judge_samples", "points per strategy of the finer estimate the reported errors use", &O::judge_samples)
      .range(16, 1 << 22);
  k.integer("polygon_quads", "quad lights the polygon-lighting errors are measured with (0: none)", &O::polygon_quads)
      .range(0, 4096);
  k.integer("render_size", "pixels a side of the check render of the finished table (0: none)", &O::render_size)
      .range(0, 1024);
  k.number("polygon_tolerance", "relative tolerance of the lobe's integral over each quad light", &O::polygon_tolerance)
      .range(1e-8, 0.1);
  k.choice<bool>("fit_to", {{"lobe", false}, {"lights", true}},
                 "what an LTC is fitted to: its lobe (the cubed error), or refined on quad lights", &O::fit_to_lights);
  k.integer("training_quads", "fit_to lights: the quad lights each lobe fit is refined on (another seed than the "
            "judging lights)", &O::training_quads)
      .range(8, 4096);
  k.choice<double>("norm",
                   {{"L1", 1.0}, {"L2", 2.0}, {"L3", 3.0}, {"Linf", std::numeric_limits<double>::infinity()}},
                   "the error norm between target and model", &O::norm);
  k.choice<bool>("integrator", {{"adaptive", false}, {"qmc", true}},
                 "adaptive cubature at the optimizer's tolerance, or fixed QMC points", &O::qmc);
  k.number("tolerance", "absolute (or, where the problem says so, relative) tolerance of the error's integrals",
           &O::tolerance)
      .range(1e-14, 1.0);
  k.number("coarse_tolerance", "the tolerance while the global search still spans the whole box (cooperative "
                               "accuracy); it tightens to 'tolerance' as the search converges",
           &O::coarse_tolerance)
      .range(1e-14, 1.0);
  k.integer("max_evaluations", "integrand evaluations allowed per integral", &O::max_evaluations)
      .range(100, 1'000'000'000);
  k.integer("views", "panels of 15 x 15 view nodes per direction over the view hemisphere", &O::views).range(1, 16);
  k.integer("lobes", "spherical Gaussian lobes", &O::lobes).range(2, 16);
  k.number("window", "half-size of the window on the plane the projected lobes are compared over", &O::window)
      .range(0.01, 100.0);
  k.number("distance", "the source lobe's distance to the plane", &O::distance).range(0.01, 100.0);
  k.list_written(&O::written);
  return k;
}

spec::Schema objective_schema() { return objective_keys().schema(); }

}  // namespace pbrfit::jobs::sweep
