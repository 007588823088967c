// The result layout of a sweep (sweep_workload.hpp): a group per model and level.
#include <cstdio>

#include "pbrfit/jobs/sweep/sweep_workload.hpp"

namespace pbrfit::jobs::sweep {
namespace {

const char* transform_name(optimize::Transform t) {
  switch (t) {
    case optimize::Transform::log: return "log";
    case optimize::Transform::cosine: return "cosine";
    default: return "linear";
  }
}

std::string bounds_text(const optimize::Parameter& p) {
  char text[160];
  std::snprintf(text, sizeof text, "[%.6g, %.6g], searched in the %s domain", p.lower, p.upper,
                transform_name(p.transform));
  return text;
}

const char* policy_name(pbrfit::sweep::GlobalPolicy policy) {
  switch (policy) {
    case pbrfit::sweep::GlobalPolicy::always: return "always";
    case pbrfit::sweep::GlobalPolicy::never: return "never";
    default: return "when_poor";
  }
}

store::Table table(const std::string& name, const std::vector<std::string>& axes, const std::string& description,
                   store::ValueType type, std::map<std::string, std::string> attributes) {
  store::Table t{name, axes, description, type};
  t.attributes = std::move(attributes);
  return t;
}

std::vector<double> component_values(std::size_t count) {
  std::vector<double> values(count);
  for (std::size_t i = 0; i < count; ++i) values[i] = double(i);
  return values;
}

}  // namespace

store::Group SweepWorkload::level_group(std::size_t m, std::uint32_t level) const {
  const ModelInfo& model = models_[m];
  const auto& grid = schedule_.levels()[level];
  const auto problem_axes = settings_.problem->axes();
  store::Group g;
  g.name = group_name(m, level);
  g.description = model.description + "; level " + std::to_string(level) + " of " +
                  std::to_string(schedule_.levels().size()) + " (the last is the requested grid)";
  g.attributes = settings_.problem->attributes();
  g.attributes["problem"] = settings_.problem->description();
  g.attributes["model"] = model.name;
  g.attributes["level"] = std::to_string(level);
  g.attributes["final_level"] = level + 1 == schedule_.levels().size() ? "true" : "false";
  g.attributes["global_search"] = policy_name(settings_.fit.policy);
  for (const auto& p : model.parameters) g.attributes["bounds_" + p.name] = bounds_text(p);
  std::vector<std::string> cell_axes;
  for (std::size_t d = 0; d < grid.dimension(); ++d) {
    g.axes.push_back({grid.axes()[d].name, grid.axes()[d].values(), problem_axes[d].description});
    cell_axes.push_back(grid.axes()[d].name);
  }
  for (const auto& p : model.parameters)
    g.tables.push_back(table(p.name, cell_axes, "fitted parameter " + p.name, store::ValueType::f64, {{"role", "parameter"}}));
  g.tables.push_back(table("error", cell_axes, model.error_description, store::ValueType::f64, {{"role", "error"}}));
  g.tables.push_back(table("evaluations", cell_axes, "objective evaluations spent on the cell, every phase",
                           store::ValueType::u32, {{"role", "count"}}));
  g.tables.push_back(table("start", cell_axes, "the start the fit came from", store::ValueType::u8,
                           {{"role", "start"}, {"labels", start_code_labels}}));
  g.tables.push_back(table("global_search", cell_axes, "1 where the global search (DE) ran", store::ValueType::u8,
                           {{"role", "count"}}));
  for (const auto& output : model.outputs) {
    std::map<std::string, std::string> attributes = {{"role", output.role}};
    if (!output.anchor.empty()) attributes["anchor"] = output.anchor;
    if (!output.compares_with.empty()) attributes["compares_with"] = output.compares_with;
    auto axes = cell_axes;
    if (output.components > 1) {
      const std::string component = output.name + "_component";
      g.axes.push_back({component, component_values(output.components), "component index of " + output.name});
      axes.push_back(component);
    }
    g.tables.push_back(table(output.name, axes, output.description, output.type, std::move(attributes)));
  }
  return g;
}

store::ResultLayout SweepWorkload::layout() const {
  store::ResultLayout layout;
  for (std::size_t m = 0; m < models_.size(); ++m) {
    for (std::uint32_t level = 0; level < schedule_.levels().size(); ++level)
      layout.groups.push_back(level_group(m, level));
    for (std::size_t p = 0; p < settings_.projections.size(); ++p) layout.groups.push_back(projection_group(m, p));
    if (render_plan_) layout.groups.push_back(render_group(m));
    if (render_plan_ && render_plan_->curves) layout.groups.push_back(curves_group(m));
  }
  return layout;
}

}  // namespace pbrfit::jobs::sweep
