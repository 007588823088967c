#include "pbrfit/jobs/sweep/sweep_kind.hpp"

#include <algorithm>
#include <cstdio>
#include <set>
#include <stdexcept>

#include "pbrfit/jobs/sweep/problem_catalogue.hpp"
#include "pbrfit/jobs/sweep/sweep_workload.hpp"
#include "pbrfit/sweep/hierarchy.hpp"

namespace pbrfit::jobs::sweep {
namespace {

using pbrfit::sweep::GridAxis;

// An engine's message without its "module: " prefix, to follow the key it is reported at.
std::string engine_reason(const std::exception& e) {
  const std::string text = e.what();
  const auto colon = text.find(": ");
  return colon != std::string::npos && colon < 12 ? text.substr(colon + 2) : text;
}

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// "; did you mean 'x'?" when a candidate is close.
std::string hint(const std::string& word, const std::vector<std::string>& candidates) {
  const std::string closest = spec::closest_match(word, candidates);
  return closest.empty() ? "" : "; did you mean '" + closest + "'?";
}

std::string listed(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

void reject_unused_objective_keys(const spec::Section& objective, const ProblemEntry& problem) {
  const spec::Schema schema = objective_schema();
  for (const auto& key : schema.fields()) {
    if (objective.given(key.name) && std::ranges::find(problem.objective_keys, key.name) == problem.objective_keys.end())
      objective.reject(key.name, "is not used by problem '" + problem.name + "' (it reads: " +
                                     (problem.objective_keys.empty() ? "none" : listed(problem.objective_keys)) + ")");
  }
}

std::vector<std::size_t> chosen_models(const spec::Section& s, const std::vector<ModelInfo>& models) {
  std::vector<std::string> names;
  for (const auto& m : models) names.push_back(m.name);
  std::vector<std::size_t> chosen;
  if (!s.given("models")) {
    for (std::size_t k = 0; k < models.size(); ++k) chosen.push_back(k);
    return chosen;
  }
  for (const auto& name : s.get_string_list("models")) {
    const auto found = std::ranges::find(names, name);
    if (found == names.end())
      s.reject("models", "names '" + name + "', not a model of the problem (" + listed(names) + ")" + hint(name, names));
    const auto index = std::size_t(found - names.begin());
    if (std::ranges::find(chosen, index) != chosen.end()) s.reject("models", "names '" + name + "' twice");
    chosen.push_back(index);
  }
  return chosen;
}

void apply_axis(const spec::Section& item, const ProblemAxis& info, GridAxis& axis) {
  if (item.given("from")) axis.lower = item.get_number("from");
  if (item.given("to")) axis.upper = item.get_number("to");
  if (item.given("count")) axis.count = std::size_t(item.get_int("count"));
  if (item.given("samples"))
    axis.placement = item.get_string("samples") == "centres" ? pbrfit::sweep::Placement::centres
                                                               : pbrfit::sweep::Placement::edges;
  const auto range = "must lie in [" + number_text(info.min) + ", " + number_text(info.max) + "] for this problem";
  if (axis.lower < info.min || axis.lower > info.max) item.reject(item.given("from") ? "from" : "to", range);
  if (axis.upper < info.min || axis.upper > info.max) item.reject(item.given("to") ? "to" : "from", range);
  try {
    pbrfit::sweep::validate(axis);
  } catch (const std::invalid_argument& e) {
    item.reject(item.given("count") ? "count" : "name", "gives an invalid axis: " + engine_reason(e));
  }
}

std::vector<GridAxis> grid_axes(const spec::Section& s, const std::vector<ProblemAxis>& infos) {
  std::vector<GridAxis> axes;
  std::vector<std::string> names;
  for (const auto& info : infos) {
    axes.push_back(info.default_axis);
    names.push_back(info.name);
  }
  std::set<std::string> seen;
  for (const auto& item : s.get_section_list("axes")) {
    const std::string& name = item.get_string("name");
    const auto found = std::ranges::find(names, name);
    if (found == names.end())
      item.reject("name", "is '" + name + "', not an axis of the problem (" + listed(names) + ")" + hint(name, names));
    if (!seen.insert(name).second) item.reject("name", "is '" + name + "' a second time");
    const auto d = std::size_t(found - names.begin());
    apply_axis(item, infos[d], axes[d]);
  }
  return axes;
}

std::optional<pbrfit::sweep::Marching> marching(const spec::Section& s, const std::vector<GridAxis>& axes) {
  if (!s.has("march")) return std::nullopt;
  const auto& march = s.get_section("march");
  const std::string& name = march.get_string("axis");
  for (std::size_t d = 0; d < axes.size(); ++d)
    if (axes[d].name == name) return pbrfit::sweep::Marching{d, march.get_bool("reverse")};
  std::vector<std::string> names;
  for (const auto& a : axes) names.push_back(a.name);
  march.reject("axis", "is '" + name + "', not an axis of the problem (" + listed(names) + ")" + hint(name, names));
}

std::vector<std::size_t> projections(const spec::Section& s, const std::vector<GridAxis>& axes) {
  std::vector<std::string> names;
  for (const auto& a : axes) names.push_back(a.name);
  std::vector<std::size_t> out;
  for (const auto& name : s.get_string_list("projections")) {
    const auto found = std::ranges::find(names, name);
    if (found == names.end())
      s.reject("projections", "names '" + name + "', not an axis of the problem (" + listed(names) + ")" + hint(name, names));
    const auto d = std::size_t(found - names.begin());
    if (std::ranges::find(out, d) != out.end()) s.reject("projections", "names '" + name + "' twice");
    if (axes.size() < 2) s.reject("projections", "needs a grid of at least two axes");
    out.push_back(d);
  }
  return out;
}

void apply_parameter(const spec::Section& item, optimize::Parameter& p) {
  if (item.given("lower")) p.lower = item.get_number("lower");
  if (item.given("upper")) p.upper = item.get_number("upper");
  if (item.given("transform")) {
    const std::string& t = item.get_string("transform");
    p.transform = t == "log" ? optimize::Transform::log : t == "cosine" ? optimize::Transform::cosine
                                                                        : optimize::Transform::linear;
  }
  try {
    optimize::validate(p);
  } catch (const std::invalid_argument& e) {
    item.reject(item.given("lower") ? "lower" : item.given("upper") ? "upper" : "transform",
                "gives an invalid parameter: " + engine_reason(e));
  }
}

std::vector<std::vector<optimize::Parameter>> parameters(const spec::Section& s, const std::vector<ModelInfo>& models,
                                                         const std::vector<std::size_t>& chosen) {
  std::vector<std::vector<optimize::Parameter>> out;
  for (std::size_t k : chosen) out.push_back(models[k].parameters);
  for (const auto& item : s.get_section_list("parameters")) {
    bool applied = false;
    for (std::size_t k = 0; k < chosen.size(); ++k) {
      if (item.given("model") && item.get_string("model") != models[chosen[k]].name) continue;
      for (auto& p : out[k])
        if (p.name == item.get_string("name")) apply_parameter(item, p), applied = true;
    }
    if (!applied) item.reject("name", "is '" + item.get_string("name") + "', not a parameter of the chosen models");
  }
  return out;
}

pbrfit::sweep::CellFitOptions fit_options(const spec::Section& fit) {
  pbrfit::sweep::CellFitOptions o;
  const std::string& policy = fit.get_string("global_search");
  o.policy = policy == "always" ? pbrfit::sweep::GlobalPolicy::always
             : policy == "never" ? pbrfit::sweep::GlobalPolicy::never
                                 : pbrfit::sweep::GlobalPolicy::when_poor;
  o.poor_ratio = fit.get_number("poor_ratio");
  o.poor_absolute = fit.get_number("poor_absolute");
  o.warm_evaluations = std::size_t(fit.get_int("warm_evaluations"));
  o.warm_search.initial_step = fit.get_number("warm_step");
  o.warm_search.restart_step = fit.get_number("warm_step") / 2;
  o.warm_search.x_tolerance = 1e-4;
  o.warm_search.f_tolerance_relative = 1e-5;
  o.warm_search.max_restarts = 3;
  o.warm_search.restart_gain_relative = 1e-4;
  o.global.max_evaluations = std::size_t(fit.get_int("max_evaluations"));
  return o;
}

// Keys that only problem `expression` reads.
void reject_expression_keys(const spec::Section& s) {
  if (s.has("expression")) s.reject("expression", "applies to problem 'expression' only");
  for (const auto& item : s.get_section_list("parameters"))
    if (item.given("start")) item.reject("start", "applies to problem 'expression' only");
}

std::unique_ptr<runtime::Workload> make_sweep(const spec::JobSpec& job) {
  return std::make_unique<SweepWorkload>(sweep_settings(job.kind_section));
}

}  // namespace

SweepSettings sweep_settings(const spec::Section& s) {
  const ProblemEntry& entry = find_problem(s.get_string("problem"));
  reject_unused_objective_keys(s.get_section("objective"), entry);
  if (entry.name != "expression") reject_expression_keys(s);
  if (entry.name != "ltc" && s.given("brdf")) s.reject("brdf", "applies to problem 'ltc' only");
  SweepSettings settings;
  settings.problem = entry.make(s);
  const auto models = settings.problem->models();
  settings.models = chosen_models(s, models);
  settings.parameters = parameters(s, models, settings.models);
  settings.axes = grid_axes(s, settings.problem->axes());
  settings.levels = std::size_t(s.get_int("levels"));
  const std::size_t possible = pbrfit::sweep::max_level_count(settings.axes);
  if (settings.levels > possible)
    s.reject("levels", "is " + std::to_string(settings.levels) + ", but this grid can be halved into at most " +
                           std::to_string(possible) + " levels");
  settings.marching = marching(s, settings.axes);
  settings.projections = projections(s, settings.axes);
  settings.fit = fit_options(s.get_section("fit"));
  settings.fit.global.tolerance = settings.problem->tolerance_schedule();
  return settings;
}

JobKind sweep_kind() {
  return {"sweep", "hierarchical parameter sweeps: DE -> Nelder-Mead fits per grid cell, warm-started", sweep_schema(),
          make_sweep};
}

}  // namespace pbrfit::jobs::sweep
