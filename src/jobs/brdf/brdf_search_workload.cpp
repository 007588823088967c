#include "pbrfit/jobs/brdf/brdf_search_workload.hpp"

#include <algorithm>
#include <stdexcept>

#include "pbrfit/gp/expression_printer.hpp"
#include "pbrfit/jobs/brdf/brdf_inputs.hpp"
#include "pbrfit/jobs/brdf/candidate_score.hpp"
#include "search_records.hpp"

namespace pbrfit::jobs::brdf {

const char* member_name(EvaluatedMember member) {
  switch (member) {
    case EvaluatedMember::comparable: return "comparable";
    case EvaluatedMember::knee: return "knee";
    case EvaluatedMember::best: return "best";
  }
  return "?";
}

BrdfSearchWorkload::BrdfSearchWorkload(BrdfSearchSettings settings) : settings_(std::move(settings)) {}

BrdfSearchWorkload::Role BrdfSearchWorkload::role(WorkItemId id) const {
  if (id.stage == front_stage()) return Role::front;
  if (id.stage == front_stage() + 1) return Role::material;
  if (id.stage == front_stage() + 2) return Role::averages;
  if (id.stage % 2 == 1) return Role::evaluation;
  return id.item == settings_.islands ? Role::front : Role::breeding;
}

std::uint32_t BrdfSearchWorkload::stage_count() const {
  return front_stage() + (settings_.evaluation.enabled ? 3 : 1);
}

std::size_t BrdfSearchWorkload::evaluated_materials() const {
  return settings_.evaluation.training.size() + settings_.evaluation.testing.size();
}

std::uint64_t BrdfSearchWorkload::item_count(std::uint32_t stage) const {
  if (stage == front_stage() || stage == front_stage() + 2) return 1;
  if (stage == front_stage() + 1) return evaluated_materials();
  return stage % 2 == 0 ? settings_.islands + 1 : chunks();
}

std::uint32_t BrdfSearchWorkload::kept_through(WorkItemId id) const {
  switch (role(id)) {
    case Role::breeding: return id.stage + 2;  // the evaluation's context, then the next breeding and front
    case Role::front: return id.stage == front_stage() ? id.stage + (settings_.evaluation.enabled ? 1 : 0) : id.stage + 2;
    case Role::evaluation: return id.stage + 1;
    case Role::material: return id.stage + 1;
    case Role::averages: return id.stage;
  }
  return id.stage;
}

Bytes BrdfSearchWorkload::item_input(std::uint32_t stage, std::uint64_t item, const ItemResults& kept) const {
  switch (role({stage, item})) {
    case Role::breeding: return breeding_input(stage, item, kept);
    case Role::front: return front_input(stage, kept);
    case Role::evaluation: return {};  // the stage context holds the trees
    case Role::material: return material_input(kept);
    case Role::averages: return averages_input(kept);
  }
  return {};
}

Bytes BrdfSearchWorkload::compute(const runtime::ItemTask& task) const {
  switch (role(task.id)) {
    case Role::breeding: return breed(task);
    case Role::front: return keep_front(task);
    case Role::evaluation: return evaluate(task);
    case Role::material: return evaluate_material(task);
    case Role::averages: return average(task);
  }
  return {};
}

// Fits trees chunk x item .. chunk x (item + 1) - 1 of the context's distinct trees.
Bytes BrdfSearchWorkload::evaluate(const runtime::ItemTask& task) const {
  ByteReader in(task.context);
  const double abandon_above = in.get<double>();
  const std::size_t distinct = in.get_varint(), first = task.id.item * settings_.chunk;
  const std::size_t last = std::min(distinct, first + settings_.chunk);
  EvaluationRecord record;
  if (first >= last) return encode(record);
  for (std::size_t k = 0; k < first; ++k) read_tree(in, brdf_input_count, brdf_parameter_count);
  for (std::size_t k = first; k < last; ++k) {
    const gp::SyntaxTree tree = read_tree(in, brdf_input_count, brdf_parameter_count);
    const auto compiled = gp::compile(tree, brdf_parameter_count);
    CandidateScore score;
    if (compiled) score = score_candidate(*compiled, *settings_.data, settings_.fit, task.random(k - first), abandon_above);
    record.errors.push_back(score.error);
    record.sizes.push_back(double(tree.size()));
    score.material_errors.resize(settings_.data->materials(), gp::worst_error);
    record.material_errors.push_back(score.material_errors);
    record.abandoned.push_back(score.abandoned ? 1 : 0);
    if (task.stop_requested()) throw runtime::Cancelled();
  }
  return encode(record);
}

std::string BrdfSearchWorkload::expression(const gp::SyntaxTree& tree) const {
  const auto compiled = gp::compile(tree, brdf_parameter_count);
  if (!compiled) return "(too long to compile)";
  std::string text = gp::print_expression(compiled->program, {pbrfit::brdf::direction_input_names(), brdf_parameter_names()},
                                          compiled->parameter_slots);
  for (std::size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at)) text.replace(at, 1, "; ");
  return text;
}

}  // namespace pbrfit::jobs::brdf
