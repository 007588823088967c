#include "pbrfit/jobs/sweep/problem_catalogue.hpp"

#include <limits>
#include <stdexcept>

#include "pbrfit/core/error.hpp"
#include "pbrfit/jobs/sweep/objective_keys.hpp"
#include "pbrfit/jobs/sweep/multi_lobe_sg_problem.hpp"
#include "pbrfit/jobs/sweep/parallax_problem.hpp"
#include "pbrfit/jobs/sweep/sphere_light_problem.hpp"

namespace pbrfit::jobs::sweep {
namespace {

std::unique_ptr<SweepProblem> make_sphere_light(const spec::Section& sweep) {
  const auto& objective = sweep.get_section("objective");
  SphereLightSettings settings;
  settings.norm_p = norm_p(objective);
  settings.view_panels = objective.given("views") ? int(objective.get_int("views")) : settings.view_panels;
  settings.truth = integration(objective, 1e-4);
  return make_sphere_light_problem(settings);
}

std::unique_ptr<SweepProblem> make_multi_lobe_sg(const spec::Section& sweep) {
  const auto& objective = sweep.get_section("objective");
  MultiLobeSgSettings settings;
  settings.lobes = count_or(objective, "lobes", settings.lobes);
  settings.samples_per_strategy = count_or(objective, "samples", settings.samples_per_strategy);
  return make_multi_lobe_sg_problem(settings);
}

std::unique_ptr<SweepProblem> make_parallax(const spec::Section& sweep, ParallaxStudy study) {
  const auto& objective = sweep.get_section("objective");
  ParallaxSettings settings;
  settings.study = study;
  if (objective.given("window")) settings.window = objective.get_number("window");
  if (objective.given("distance")) settings.distance = objective.get_number("distance");
  settings.integration = integration(objective, 1e-5);
  settings.coarse_tolerance = coarse_tolerance(objective, settings.integration.abs_tolerance, 1e-3);
  return make_parallax_problem(settings);
}

}  // namespace

const std::vector<ProblemEntry>& problem_catalogue() {
  static const std::vector<ProblemEntry> entries = {
      {"ltc_ggx", "isotropic LTC table of GGX (Heitz et al. 2016) on the published grid, beside the published table",
       {"samples", "judge_samples", "polygon_quads", "polygon_tolerance", "fit_to"}, make_ltc_ggx},
      {"ltc", "isotropic LTC tables of the built-in BRDF families, a BRDF expression or a measured material",
       {"samples", "judge_samples", "polygon_quads", "polygon_tolerance", "fit_to"}, make_ltc},
      {"sphere_light", "GGX lit by a spherical light: roughness modification, capped, representative point models",
       {"norm", "tolerance", "max_evaluations", "views"}, make_sphere_light},
      {"multi_lobe_sg", "multi-lobe spherical Gaussian kernel for GGX environment lighting", {"samples", "lobes"},
       make_multi_lobe_sg},
      {"parallax_distance", "parallax-corrected probes: roughness of a perpendicular lobe over roughness x distance",
       {"tolerance", "coarse_tolerance", "max_evaluations", "window"},
       [](const spec::Section& o) { return make_parallax(o, ParallaxStudy::distance); }},
      {"parallax_angle", "parallax-corrected probes: roughness and shift of a perpendicular lobe over roughness x angle",
       {"tolerance", "coarse_tolerance", "max_evaluations", "window", "distance"},
       [](const spec::Section& o) { return make_parallax(o, ParallaxStudy::angle); }},
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

spec::Schema objective_schema() {
  spec::Schema s("objective");
  s.integer("samples", "points per sampling strategy of the objective's quasi-Monte Carlo estimate").range(16, 1 << 22);
  s.integer("judge_samples", "points per strategy of the finer estimate the reported errors use").range(16, 1 << 22);
  s.integer("polygon_quads", "quad lights the polygon-lighting errors are measured with (0: none)").range(0, 4096);
  s.number("polygon_tolerance", "relative tolerance of the lobe's integral over each quad light").range(1e-8, 0.1);
  s.choice("fit_to", {"lobe", "lights"}, "what an LTC is fitted to: its lobe (the cubed error), or refined on quad lights");
  s.choice("norm", {"L1", "L2", "L3", "Linf"}, "the error norm between target and model");
  s.choice("integrator", {"adaptive", "qmc"}, "adaptive cubature at the optimizer's tolerance, or fixed QMC points");
  s.number("tolerance", "absolute (or, where the problem says so, relative) tolerance of the error's integrals")
      .range(1e-14, 1.0);
  s.number("coarse_tolerance", "the tolerance while the global search still spans the whole box (cooperative "
                               "accuracy); it tightens to 'tolerance' as the search converges")
      .range(1e-14, 1.0);
  s.integer("max_evaluations", "integrand evaluations allowed per integral").range(100, 1'000'000'000);
  s.integer("views", "panels of 15 x 15 view nodes per direction over the view hemisphere").range(1, 16);
  s.integer("lobes", "spherical Gaussian lobes").range(2, 16);
  s.number("window", "half-size of the window on the plane the projected lobes are compared over").range(0.01, 100.0);
  s.number("distance", "the source lobe's distance to the plane").range(0.01, 100.0);
  return s;
}

}  // namespace pbrfit::jobs::sweep
