#include "pbrfit/jobs/sweep/sweep_kind.hpp"

#include <algorithm>
#include <cstdio>
#include <set>
#include <stdexcept>

#include "pbrfit/jobs/sweep/problem_catalogue.hpp"
#include "pbrfit/jobs/sweep/sweep_keys.hpp"
#include "pbrfit/jobs/sweep/sweep_workload.hpp"
#include "pbrfit/sweep/hierarchy.hpp"

namespace pbrfit::jobs::sweep {
namespace {

using pbrfit::sweep::GridAxis;

std::string bound_text(double value) {
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

void reject_unused_objective_keys(const ObjectiveKeys& objective, const ProblemEntry& problem) {
  for (const spec::WrittenKey& key : objective.written)
    if (std::ranges::find(problem.objective_keys, key.key) == problem.objective_keys.end())
      key.reject("is not used by problem '" + problem.name + "' (it reads: " +
                 (problem.objective_keys.empty() ? "none" : listed(problem.objective_keys)) + ")");
}

std::vector<std::size_t> chosen_models(const SweepKeys& s, const std::vector<ModelInfo>& models) {
  std::vector<std::string> names;
  for (const auto& m : models) names.push_back(m.name);
  std::vector<std::size_t> chosen;
  if (!s.models.written) {
    for (std::size_t k = 0; k < models.size(); ++k) chosen.push_back(k);
    return chosen;
  }
  for (const auto& name : s.models.value) {
    const auto found = std::ranges::find(names, name);
    if (found == names.end())
      s.models.reject("names '" + name + "', not a model of the problem (" + listed(names) + ")" + hint(name, names));
    const auto index = std::size_t(found - names.begin());
    if (std::ranges::find(chosen, index) != chosen.end()) s.models.reject("names '" + name + "' twice");
    chosen.push_back(index);
  }
  return chosen;
}

void apply_axis(const AxisKeys& item, const ProblemAxis& info, GridAxis& axis) {
  if (item.from.written) axis.lower = item.from.value;
  if (item.to.written) axis.upper = item.to.value;
  if (item.count.written) axis.count = std::size_t(item.count.value);
  if (item.samples.written) axis.placement = item.samples.value;
  const auto range = "must lie in [" + bound_text(info.min) + ", " + bound_text(info.max) + "] for this problem";
  if (axis.lower < info.min || axis.lower > info.max) (item.from.written ? item.from : item.to).reject(range);
  if (axis.upper < info.min || axis.upper > info.max) (item.to.written ? item.to : item.from).reject(range);
  if (const std::string reason = pbrfit::sweep::invalid_reason(axis); !reason.empty()) {
    const std::string message = "gives an invalid axis: " + reason;
    if (item.count.written) item.count.reject(message);
    item.name.reject(message);
  }
}

std::vector<GridAxis> grid_axes(const SweepKeys& s, const std::vector<ProblemAxis>& infos) {
  std::vector<GridAxis> axes;
  std::vector<std::string> names;
  for (const auto& info : infos) {
    axes.push_back(info.default_axis);
    names.push_back(info.name);
  }
  std::set<std::string> seen;
  for (const AxisKeys& item : s.axes.value) {
    const std::string& name = item.name.value;
    const auto found = std::ranges::find(names, name);
    if (found == names.end())
      item.name.reject("is '" + name + "', not an axis of the problem (" + listed(names) + ")" + hint(name, names));
    if (!seen.insert(name).second) item.name.reject("is '" + name + "' a second time");
    const auto d = std::size_t(found - names.begin());
    apply_axis(item, infos[d], axes[d]);
  }
  return axes;
}

// The index of the grid's axis `name`, which `key` (written as "KEY VERB 'name'") names; refused at the key
// when the grid has no such axis.
template <class Key>
std::size_t axis_index(const Key& key, const std::string& verb, const std::string& name,
                       const std::vector<GridAxis>& axes) {
  std::vector<std::string> names;
  for (const auto& a : axes) names.push_back(a.name);
  const auto found = std::ranges::find(names, name);
  if (found == names.end())
    key.reject(verb + " '" + name + "', not an axis of the problem (" + listed(names) + ")" + hint(name, names));
  return std::size_t(found - names.begin());
}

std::optional<pbrfit::sweep::Marching> marching(const SweepKeys& s, const std::vector<GridAxis>& axes) {
  if (!s.march) return std::nullopt;
  return pbrfit::sweep::Marching{axis_index(s.march->axis, "is", s.march->axis.value, axes), s.march->reverse};
}

std::vector<std::size_t> projections(const SweepKeys& s, const std::vector<GridAxis>& axes) {
  std::vector<std::size_t> out;
  for (const auto& name : s.projections.value) {
    const std::size_t d = axis_index(s.projections, "names", name, axes);
    if (std::ranges::find(out, d) != out.end()) s.projections.reject("names '" + name + "' twice");
    if (axes.size() < 2) s.projections.reject("needs a grid of at least two axes");
    out.push_back(d);
  }
  return out;
}

void apply_parameter(const ParameterKeys& item, optimize::Parameter& p) {
  if (item.lower.written) p.lower = item.lower.value;
  if (item.upper.written) p.upper = item.upper.value;
  if (item.transform.written) p.transform = item.transform.value;
  if (const std::string reason = optimize::invalid_reason(p); !reason.empty()) {
    const std::string message = "gives an invalid parameter: " + reason;
    if (item.lower.written) item.lower.reject(message);
    if (item.upper.written) item.upper.reject(message);
    item.transform.reject(message);
  }
}

std::vector<std::vector<optimize::Parameter>> parameters(const SweepKeys& s, const std::vector<ModelInfo>& models,
                                                         const std::vector<std::size_t>& chosen) {
  std::vector<std::vector<optimize::Parameter>> out;
  for (std::size_t k : chosen) out.push_back(models[k].parameters);
  for (const ParameterKeys& item : s.parameters.value) {
    bool applied = false;
    for (std::size_t k = 0; k < chosen.size(); ++k) {
      if (item.model.written && item.model.value != models[chosen[k]].name) continue;
      for (auto& p : out[k])
        if (p.name == item.name.value) apply_parameter(item, p), applied = true;
    }
    if (!applied) item.name.reject("is '" + item.name.value + "', not a parameter of the chosen models");
  }
  return out;
}

pbrfit::sweep::CellFitOptions fit_options(const FitKeys& fit) {
  pbrfit::sweep::CellFitOptions o;
  o.policy = fit.global_search;
  o.poor_ratio = fit.poor_ratio;
  o.poor_absolute = fit.poor_absolute;
  o.warm_evaluations = fit.warm_evaluations;
  o.warm_search.initial_step = fit.warm_step;
  o.warm_search.restart_step = fit.warm_step / 2;
  o.warm_search.x_tolerance = 1e-4;
  o.warm_search.f_tolerance_relative = 1e-5;
  o.warm_search.max_restarts = 3;
  o.warm_search.restart_gain_relative = 1e-4;
  o.global.max_evaluations = fit.max_evaluations;
  return o;
}

// Keys that only problem `expression` reads.
void reject_expression_keys(const SweepKeys& s) {
  if (s.expression.written) s.expression.reject("applies to problem 'expression' only");
  for (const ParameterKeys& item : s.parameters.value)
    if (item.start.written) item.start.reject("applies to problem 'expression' only");
}

std::unique_ptr<runtime::Workload> make_sweep(const spec::JobSpec& job) {
  return std::make_unique<SweepWorkload>(sweep_settings(job.kind_section));
}

// A fit per cell: 4 Mi cells (2,048 x 2,048) is far beyond any table a sweep finishes, and bounds what the
// schedule allocates for a job file's axes (two axes of 2^20 would ask for 2^40 cells).
constexpr std::size_t max_sweep_cells = std::size_t{1} << 22;

void reject_huge_grid(const SweepKeys& s, const std::vector<pbrfit::sweep::GridAxis>& axes) {
  std::size_t cells = 1;
  for (const auto& axis : axes) {
    if (axis.count > max_sweep_cells / cells)
      s.axes.reject("make a grid of more than " + std::to_string(max_sweep_cells) + " cells (4 Mi, a fit each)");
    cells *= axis.count;
  }
}

// The settings the keys describe, checked against the problem they name.
SweepSettings settings_of(const SweepKeys& s) {
  const ProblemEntry& entry = find_problem(s.problem.value);
  reject_unused_objective_keys(s.objective, entry);
  if (entry.name != "expression") reject_expression_keys(s);
  if (entry.name != "ltc" && s.brdf.written) s.brdf.reject("applies to problem 'ltc' only");
  SweepSettings settings;
  settings.problem = entry.make(s);
  const auto models = settings.problem->models();
  settings.models = chosen_models(s, models);
  settings.parameters = parameters(s, models, settings.models);
  settings.axes = grid_axes(s, settings.problem->axes());
  reject_huge_grid(s, settings.axes);
  settings.levels = std::size_t(s.levels.value);
  const std::size_t possible = pbrfit::sweep::max_level_count(settings.axes);
  if (settings.levels > possible)
    s.levels.reject("is " + std::to_string(settings.levels) + ", but this grid can be halved into at most " +
                    std::to_string(possible) + " levels");
  settings.marching = marching(s, settings.axes);
  settings.projections = projections(s, settings.axes);
  settings.fit = fit_options(s.fit);
  settings.fit.global.tolerance = settings.problem->tolerance_schedule();
  return settings;
}

}  // namespace

SweepSettings sweep_settings(const spec::Section& sweep) { return settings_of(sweep_keys().read(sweep)); }

JobKind sweep_kind() {
  return {"sweep", "hierarchical parameter sweeps: DE -> Nelder-Mead fits per grid cell, warm-started",
          sweep_keys().schema(), make_sweep};
}

}  // namespace pbrfit::jobs::sweep
