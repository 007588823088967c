// The keys of a `brdf_search` job's section (docs/job-files.md, kind `brdf_search`), each bound to what it
// fills in the section as written (brdf_search_section.hpp); brdf_search_kind.cpp turns that into settings.
#include <numbers>

#include "brdf_search_section.hpp"
#include "pbrfit/jobs/brdf/material_sets.hpp"
#include "pbrfit/jobs/brdf/material_source.hpp"
#include "pbrfit/jobs/brdf/seed_brdfs.hpp"

namespace pbrfit::jobs::brdf {
namespace {

using std::int64_t;

std::vector<std::string> seed_names() {
  std::vector<std::string> names;
  for (const auto& s : seed_brdfs()) names.push_back(s.name);
  return names;
}

spec::Keys<gp::ParameterFitOptions> fit_keys(int64_t starts, int64_t evaluations) {
  using F = gp::ParameterFitOptions;
  spec::Keys<F> k("fit");
  k.integer("starts", "Nelder-Mead searches from random points per material and channel", &F::starts)
      .range(1, 1000)
      .defaults_to(starts);
  k.integer("evaluations_per_start", "metric evaluations per search", &F::evaluations_per_start)
      .range(1, 1'000'000)
      .defaults_to(evaluations);
  k.number("lower", "parameters are searched within [lower, upper]", &F::lower).defaults_to(-20.0);
  k.number("upper", "see lower", &F::upper).defaults_to(20.0);
  k.number("start_lower", "random starts are uniform in [start_lower, start_upper]", &F::start_lower).defaults_to(0.0);
  k.number("start_upper", "see start_lower", &F::start_upper).defaults_to(1.0);
  k.boolean("warm_start", "the first search of each fit starts from the previous channel's or material's fit",
            &F::warm_start)
      .defaults_to(true);
  k.check("upper", [](F& f) -> std::string { return f.lower >= f.upper ? "must be above 'lower'" : ""; });
  k.check("start_upper",
          [](F& f) -> std::string { return f.start_lower > f.start_upper ? "must be at least 'start_lower'" : ""; });
  k.check("start_lower", [](F& f) -> std::string {
    return f.start_lower < f.lower || f.start_upper > f.upper ? "starts must lie within [lower, upper]" : "";
  });
  return k;
}

spec::Keys<EvaluateSection> evaluation_keys() {
  using E = EvaluateSection;
  spec::Keys<E> k("evaluate");
  k.boolean("enabled", "fit, render and compare the seed and the found BRDFs after the search", &E::enabled)
      .defaults_to(true);
  k.string_list("references", 0, 8,
                "named BRDFs fitted, rendered and compared beside the seed, never searched (the paper's own: "
                "brady_metal, brady_dielectric)",
                &E::references, seed_names())
      .defaults_to(std::vector<std::string>{});
  k.string_list("members", 0, 3, "the front members evaluated beside the seed",
                [](E& e, const std::vector<std::string>& names) {
                  e.members.clear();
                  for (const auto& m : names)
                    e.members.push_back(m == "knee"   ? EvaluatedMember::knee
                                        : m == "best" ? EvaluatedMember::best
                                                      : EvaluatedMember::comparable);
                },
                {"comparable", "knee", "best"})
      .defaults_to(std::vector<std::string>{"comparable", "knee"});
  k.number("comparable_size", "`comparable`: the most accurate member at most this many times the seed's size",
           &E::comparable_size)
      .range(0.01, 100.0)
      .defaults_to(1.5);
  k.section("fit", fit_keys(16, 1000), "the fits of the evaluation (more thorough than the search's)", &E::fit);
  add_sampling_keys(k, 128, 64);  // the renders: the scene's light, finer
  k.number("exposure", "the renders' exposure, before the sRGB encoding", &E::exposure).above(0.0).defaults_to(1.0);
  return k;
}

}  // namespace

spec::Keys<BrdfSearchSection> brdf_search_keys() {
  using S = BrdfSearchSection;
  spec::Keys<S> k("brdf_search");
  k.choice("materials", {"metals", "dielectrics", "custom"}, "the paper's material class, or custom lists", &S::materials)
      .defaults_to(std::string("metals"));
  k.string_list("training", 1, 100, "the materials searched on (default: the class's four)", &S::training,
                merl_material_names());
  k.string_list("testing", 0, 100, "the held-out materials (default: the class's sixteen)", &S::testing,
                merl_material_names());
  k.string("merl_directory", "a directory of real MERL .binary files (default: the built-in stand-ins)",
           &S::merl_directory)
      .defaults_to(std::string(""));
  k.string("cache", "where stand-ins evaluated on the MERL grid are kept as .binary files ('' for none)", &S::cache)
      .defaults_to(std::string(default_material_cache));
  k.section("scene", scene_keys(), "the sphere, its lighting and the metric's pruning", &S::scene);
  k.choice("seed_brdf", seed_names(), "the BRDF the edits start from", &S::seed_brdf)
      .defaults_to(std::string("cook_torrance"));
  k.string_list("codebank", 0, 16, "further BRDFs whose sub-expressions Insert edits may use", &S::codebank, seed_names())
      .defaults_to(std::vector<std::string>{"blinn_phong", "ggx_smith"});
  k.string_list("unary", 1, 9, "unary operators of Replace edits", &S::unary,
                {"neg", "sin", "cos", "tan", "exp", "asin", "acos", "atan", "sqrt"})
      .defaults_to(std::vector<std::string>{"neg", "sin", "cos", "tan", "exp", "asin", "acos", "atan", "sqrt"});
  k.string_list("binary", 1, 7, "binary operators of Replace edits", &S::binary,
                {"add", "sub", "mul", "div", "max", "min", "pow"})
      .defaults_to(std::vector<std::string>{"add", "sub", "mul", "div", "max", "min", "pow"});
  k.number_list("constants", 0, 16, "constants of Replace edits", &S::constants)
      .defaults_to(std::vector<double>{1.0, 2.0, std::numbers::pi, 4.0});
  k.integer("islands", "islands on a ring", &S::islands).range(1, 4096).defaults_to(int64_t{4});
  k.integer("population", "genomes per island (even)", &S::population).range(2, 1'000'000).defaults_to(int64_t{256});
  k.integer("generations", "generations per island", &S::generations).range(1, 1'000'000).defaults_to(int64_t{100});
  k.integer("migration_interval", "generations between migrations", &S::migration_interval)
      .range(1, 1'000'000)
      .defaults_to(int64_t{5});
  k.integer("migrants", "the best genomes each island sends to the next", &S::migrants)
      .range(0, 1'000'000)
      .defaults_to(int64_t{1});
  k.integer("tournament_size", "contestants per parent tournament", &S::tournament_size)
      .range(1, 1'000'000)
      .defaults_to(int64_t{8});
  k.integer("max_genome", "edits per genome", &S::max_genome).range(1, 100'000).defaults_to(int64_t{512});
  k.integer("max_nodes", "the largest tree an edit may make", &S::max_nodes).range(1, 100'000).defaults_to(int64_t{256});
  k.integer("chunk", "trees per evaluation work item", &S::chunk).range(1, 1'000'000).defaults_to(int64_t{4});
  k.boolean("abandon_poor",
            "stop fitting a candidate once its error on the first materials exceeds the previous generation's "
            "median (its error is then a lower bound; it stays out of the front)",
            &S::abandon_poor)
      .defaults_to(true);
  k.section("fit", fit_keys(3, 100), "the parameter fits of the search", &S::fit);
  k.section("evaluate", evaluation_keys(), "the evaluation after the search", &S::evaluate);
  return k;
}

}  // namespace pbrfit::jobs::brdf
