// The schema of a `sweep` job's section (docs/job-files.md, kind `sweep`).
#include "pbrfit/jobs/sweep/problem_catalogue.hpp"
#include "pbrfit/jobs/sweep/sweep_kind.hpp"

namespace pbrfit::jobs::sweep {
namespace {

spec::Schema axis_schema() {
  spec::Schema s("axis");
  s.string("name", "one of the problem's axes").require();
  s.number("from", "first value (default: the problem's)");
  s.number("to", "last value (default: the problem's)");
  s.integer("count", "samples along the axis (default: the problem's)").range(1, 1 << 20);
  s.choice("samples", {"edges", "centres"}, "edges: from and to included; centres: cell centres between them");
  return s;
}

spec::Schema march_schema() {
  spec::Schema s("march");
  s.string("axis", "the axis to march along: each step warm-starts from the one before").require();
  s.boolean("reverse", "march from the last value of the axis to the first").defaults_to(false);
  return s;
}

spec::Schema parameter_schema() {
  spec::Schema s("parameter");
  s.string("name", "a parameter of the model").require();
  s.string("model", "the model it belongs to (default: every chosen model with such a parameter)");
  s.number("lower", "lower bound (default: the model's)");
  s.number("upper", "upper bound (default: the model's)");
  s.choice("transform", {"linear", "log", "cosine"}, "the domain the optimizer searches it in");
  s.number("start", "problem 'expression': the default start (default: the middle of the bounds)");
  return s;
}

spec::Schema fit_schema() {
  spec::Schema s("fit");
  s.choice("global_search", {"when_poor", "always", "never"},
           "when the global search (DE, then Nelder-Mead) runs after the warm starts are polished")
      .defaults_to(std::string("when_poor"));
  s.number("poor_ratio", "a warm start fits poorly when its error exceeds this many times its source's error")
      .at_least(1.0)
      .defaults_to(2.0);
  s.number("poor_absolute", "... and exceeds this absolute error").at_least(0.0).defaults_to(0.0);
  s.integer("warm_evaluations", "objective evaluations for polishing a cell's warm starts").range(1, 100'000'000).defaults_to(std::int64_t{400});
  s.number("warm_step", "the warm polish's first simplex step, relative to each parameter's range")
      .range(1e-6, 1.0)
      .defaults_to(0.01);
  s.integer("max_evaluations", "objective evaluations of the global search per cell").range(10, 1'000'000'000).defaults_to(std::int64_t{20'000});
  return s;
}

}  // namespace

spec::Schema sweep_schema() {
  spec::Schema s("sweep");
  s.choice("problem", problem_names(), "what to fit (docs/job-files.md lists each problem's axes and models)").require();
  s.string_list("models", 1, spec::unbounded, "the problem's models to fit (default: all of them)");
  s.section_list("axes", axis_schema(), 0, 16, "changes to the problem's axes, by name");
  s.integer("levels", "levels of the hierarchy, coarse to fine; the last is the requested grid").range(1, 32).defaults_to(std::int64_t{1});
  s.section("march", march_schema(), "marching order within each level (default: none)");
  s.section_list("parameters", parameter_schema(), 0, spec::unbounded, "changes to the models' parameter bounds");
  s.string_list("projections", 0, 16, "axes to average the last level's fits over (a table each)")
      .defaults_to(std::vector<std::string>{});
  s.section("fit", fit_schema(), "how each cell is fitted");
  s.section("objective", objective_schema(), "the problem's error estimate (keys depend on the problem)");
  s.section("expression", expression_schema(), "problem 'expression': the domain, the target and the model");
  s.section("brdf", brdf_schema(), "problem 'ltc': a BRDF expression or a measured material to tabulate");
  return s;
}

}  // namespace pbrfit::jobs::sweep
