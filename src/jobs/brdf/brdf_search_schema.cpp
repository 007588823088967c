// The schema of a `brdf_search` job's section (docs/job-files.md, kind `brdf_search`).
#include <numbers>

#include "pbrfit/jobs/brdf/brdf_scene.hpp"
#include "pbrfit/jobs/brdf/brdf_search_kind.hpp"
#include "pbrfit/jobs/brdf/material_sets.hpp"
#include "pbrfit/jobs/brdf/seed_brdfs.hpp"

namespace pbrfit::jobs::brdf {
namespace {

using std::int64_t;

std::vector<std::string> seed_names() {
  std::vector<std::string> names;
  for (const auto& s : seed_brdfs()) names.push_back(s.name);
  return names;
}

spec::Schema fit_schema(int64_t starts, int64_t evaluations) {
  spec::Schema s("fit");
  s.integer("starts", "Nelder-Mead searches from random points per material and channel").range(1, 1000)
      .defaults_to(starts);
  s.integer("evaluations_per_start", "metric evaluations per search").range(1, 1'000'000).defaults_to(evaluations);
  s.number("lower", "parameters are searched within [lower, upper]").defaults_to(-20.0);
  s.number("upper", "see lower").defaults_to(20.0);
  s.number("start_lower", "random starts are uniform in [start_lower, start_upper]").defaults_to(0.0);
  s.number("start_upper", "see start_lower").defaults_to(1.0);
  s.boolean("warm_start", "the first search of each fit starts from the previous channel's or material's fit")
      .defaults_to(true);
  return s;
}

spec::Schema evaluation_schema() {
  spec::Schema s("evaluate");
  s.boolean("enabled", "fit, render and compare the seed and the found BRDFs after the search").defaults_to(true);
  s.string_list("references", 0, 8, "named BRDFs fitted, rendered and compared beside the seed, never searched "
                "(the paper's own: brady_metal, brady_dielectric)", seed_names())
      .defaults_to(std::vector<std::string>{});
  s.string_list("members", 0, 3, "the front members evaluated beside the seed", {"comparable", "knee", "best"})
      .defaults_to(std::vector<std::string>{"comparable", "knee"});
  s.number("comparable_size", "`comparable`: the most accurate member at most this many times the seed's size")
      .range(0.01, 100.0).defaults_to(1.5);
  s.section("fit", fit_schema(16, 1000), "the fits of the evaluation (more thorough than the search's)");
  add_sampling_keys(s, 128, 64);  // the renders: the scene's light, finer
  s.number("exposure", "the renders' exposure, before the sRGB encoding").above(0.0).defaults_to(1.0);
  return s;
}

}  // namespace

spec::Schema brdf_search_schema() {
  spec::Schema s("brdf_search");
  s.choice("materials", {"metals", "dielectrics", "custom"}, "the paper's material class, or custom lists")
      .defaults_to(std::string("metals"));
  s.string_list("training", 1, 100, "the materials searched on (default: the class's four)", merl_material_names());
  s.string_list("testing", 0, 100, "the held-out materials (default: the class's sixteen)", merl_material_names());
  s.string("merl_directory", "a directory of real MERL .binary files (default: the built-in stand-ins)")
      .defaults_to(std::string(""));
  s.string("cache", "where stand-ins evaluated on the MERL grid are kept as .binary files ('' for none)")
      .defaults_to(std::string("results/merl-cache"));
  s.section("scene", scene_schema(), "the sphere, its lighting and the metric's pruning");
  s.choice("seed_brdf", seed_names(), "the BRDF the edits start from").defaults_to(std::string("cook_torrance"));
  s.string_list("codebank", 0, 16, "further BRDFs whose sub-expressions Insert edits may use", seed_names())
      .defaults_to(std::vector<std::string>{"blinn_phong", "ggx_smith"});
  s.string_list("unary", 1, 9, "unary operators of Replace edits",
                {"neg", "sin", "cos", "tan", "exp", "asin", "acos", "atan", "sqrt"})
      .defaults_to(std::vector<std::string>{"neg", "sin", "cos", "tan", "exp", "asin", "acos", "atan", "sqrt"});
  s.string_list("binary", 1, 7, "binary operators of Replace edits", {"add", "sub", "mul", "div", "max", "min", "pow"})
      .defaults_to(std::vector<std::string>{"add", "sub", "mul", "div", "max", "min", "pow"});
  s.number_list("constants", 0, 16, "constants of Replace edits").defaults_to(std::vector<double>{1.0, 2.0, std::numbers::pi, 4.0});
  s.integer("islands", "islands on a ring").range(1, 4096).defaults_to(int64_t{4});
  s.integer("population", "genomes per island (even)").range(2, 1'000'000).defaults_to(int64_t{256});
  s.integer("generations", "generations per island").range(1, 1'000'000).defaults_to(int64_t{100});
  s.integer("migration_interval", "generations between migrations").range(1, 1'000'000).defaults_to(int64_t{5});
  s.integer("migrants", "the best genomes each island sends to the next").range(0, 1'000'000).defaults_to(int64_t{1});
  s.integer("tournament_size", "contestants per parent tournament").range(1, 1'000'000).defaults_to(int64_t{8});
  s.integer("max_genome", "edits per genome").range(1, 100'000).defaults_to(int64_t{512});
  s.integer("max_nodes", "the largest tree an edit may make").range(1, 100'000).defaults_to(int64_t{256});
  s.integer("chunk", "trees per evaluation work item").range(1, 1'000'000).defaults_to(int64_t{4});
  s.boolean("abandon_poor", "stop fitting a candidate once its error on the first materials exceeds the "
            "previous generation's median (its error is then a lower bound; it stays out of the front)")
      .defaults_to(true);
  s.section("fit", fit_schema(3, 100), "the parameter fits of the search");
  s.section("evaluate", evaluation_schema(), "the evaluation after the search");
  return s;
}

}  // namespace pbrfit::jobs::brdf
