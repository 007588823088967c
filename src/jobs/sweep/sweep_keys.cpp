// The keys of a `sweep` job's section (docs/job-files.md, kind `sweep`), bound to SweepKeys (sweep_keys.hpp).
#include "pbrfit/jobs/sweep/sweep_keys.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pbrfit/jobs/sweep/problem_catalogue.hpp"

namespace pbrfit::jobs::sweep {
namespace {

using pbrfit::sweep::GlobalPolicy;
using pbrfit::sweep::Placement;

spec::Keys<AxisKeys> axis_keys() {
  spec::Keys<AxisKeys> k("axis");
  k.string("name", "one of the problem's axes", &AxisKeys::name).require();
  k.number("from", "first value (default: the problem's)", &AxisKeys::from);
  k.number("to", "last value (default: the problem's)", &AxisKeys::to);
  k.integer("count", "samples along the axis (default: the problem's)", &AxisKeys::count).range(1, 1 << 20);
  k.choice<Placement>("samples", {{"edges", Placement::edges}, {"centres", Placement::centres}},
                      "edges: from and to included; centres: cell centres between them", &AxisKeys::samples);
  return k;
}

spec::Keys<MarchKeys> march_keys() {
  spec::Keys<MarchKeys> k("march");
  k.string("axis", "the axis to march along: each step warm-starts from the one before", &MarchKeys::axis).require();
  k.boolean("reverse", "march from the last value of the axis to the first", &MarchKeys::reverse).defaults_to(false);
  return k;
}

spec::Keys<ParameterKeys> parameter_keys() {
  using optimize::Transform;
  spec::Keys<ParameterKeys> k("parameter");
  k.string("name", "a parameter of the model", &ParameterKeys::name).require();
  k.string("model", "the model it belongs to (default: every chosen model with such a parameter)", &ParameterKeys::model);
  k.number("lower", "lower bound (default: the model's)", &ParameterKeys::lower);
  k.number("upper", "upper bound (default: the model's)", &ParameterKeys::upper);
  k.choice<Transform>("transform", {{"linear", Transform::linear}, {"log", Transform::log}, {"cosine", Transform::cosine}},
                      "the domain the optimizer searches it in", &ParameterKeys::transform);
  k.number("start", "problem 'expression': the default start (default: the middle of the bounds)", &ParameterKeys::start);
  return k;
}

spec::Keys<FitKeys> fit_keys() {
  spec::Keys<FitKeys> k("fit");
  k.choice<GlobalPolicy>("global_search",
                         {{"when_poor", GlobalPolicy::when_poor}, {"always", GlobalPolicy::always},
                          {"never", GlobalPolicy::never}},
                         "when the global search (DE, then Nelder-Mead) runs after the warm starts are polished",
                         &FitKeys::global_search)
      .defaults_to(std::string("when_poor"));
  k.number("poor_ratio", "a warm start fits poorly when its error exceeds this many times its source's error",
           &FitKeys::poor_ratio)
      .at_least(1.0)
      .defaults_to(2.0);
  k.number("poor_absolute", "... and exceeds this absolute error", &FitKeys::poor_absolute).at_least(0.0).defaults_to(0.0);
  k.integer("warm_evaluations", "objective evaluations for polishing a cell's warm starts", &FitKeys::warm_evaluations)
      .range(1, 100'000'000)
      .defaults_to(std::int64_t{400});
  k.number("warm_step", "the warm polish's first simplex step, relative to each parameter's range", &FitKeys::warm_step)
      .range(1e-6, 1.0)
      .defaults_to(0.01);
  k.integer("max_evaluations", "objective evaluations of the global search per cell", &FitKeys::max_evaluations)
      .range(10, 1'000'000'000)
      .defaults_to(std::int64_t{20'000});
  return k;
}

spec::Keys<SweepKeys> make_sweep_keys() {
  spec::Keys<SweepKeys> k("sweep");
  k.choice("problem", problem_names(), "what to fit (docs/job-files.md lists each problem's axes and models)",
           &SweepKeys::problem)
      .require();
  k.string_list("models", 1, spec::unbounded, "the problem's models to fit (default: all of them)", &SweepKeys::models);
  k.section_list("axes", axis_keys(), 0, 16, "changes to the problem's axes, by name", &SweepKeys::axes);
  k.integer("levels", "levels of the hierarchy, coarse to fine; the last is the requested grid", &SweepKeys::levels)
      .range(1, 32)
      .defaults_to(std::int64_t{1});
  k.section("march", march_keys(), "marching order within each level (default: none)", &SweepKeys::march);
  k.section_list("parameters", parameter_keys(), 0, spec::unbounded, "changes to the models' parameter bounds",
                 &SweepKeys::parameters);
  k.string_list("projections", 0, 16, "axes to average the last level's fits over (a table each)",
                &SweepKeys::projections)
      .defaults_to(std::vector<std::string>{});
  k.section("fit", fit_keys(), "how each cell is fitted", &SweepKeys::fit);
  k.section("objective", objective_keys(), "the problem's error estimate (keys depend on the problem)",
            &SweepKeys::objective);
  k.section("expression", expression_keys(), "problem 'expression': the domain, the target and the model",
            &SweepKeys::expression);
  k.section("brdf", brdf_keys(), "problem 'ltc': a BRDF expression or a measured material to tabulate",
            &SweepKeys::brdf);
  return k;
}

}  // namespace

const spec::Keys<SweepKeys>& sweep_keys() {
  static const spec::Keys<SweepKeys> keys = make_sweep_keys();
  return keys;
}

integrate::AdaptiveOptions integration(const ObjectiveKeys& objective, double tolerance_default) {
  integrate::AdaptiveOptions options;
  options.abs_tolerance = objective.tolerance.value_or(tolerance_default);
  if (objective.max_evaluations) options.max_evaluations = *objective.max_evaluations;
  return options;
}

double coarse_tolerance(const ObjectiveKeys& objective, double final_tolerance, double fallback) {
  const auto& coarse = objective.coarse_tolerance;
  const double value = coarse.written ? coarse.value : std::max(fallback, final_tolerance);
  if (value < final_tolerance) coarse.reject("must be at least 'tolerance'");
  return value;
}

gp::ParsedExpression parse_expression_at(const spec::Located<std::string>& text, const gp::ExpressionNames& names) {
  const auto result = gp::parse_expression(text.value, names);
  if (const auto* error = std::get_if<gp::ExpressionError>(&result))
    text.reject("has an error at line " + std::to_string(error->line) + ", column " + std::to_string(error->column) +
                " of its expression: " + error->message);
  return std::get<gp::ParsedExpression>(result);
}

}  // namespace pbrfit::jobs::sweep
