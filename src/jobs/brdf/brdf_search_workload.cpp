#include "pbrfit/jobs/brdf/brdf_search_workload.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

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

BrdfSearchWorkload::BrdfSearchWorkload(BrdfSearchSettings settings) : settings_(std::move(settings)) {
  using runtime::stage;
  using runtime::parts;
  using Self = BrdfSearchWorkload;
  using Trees = std::vector<gp::SyntaxTree>;
  using Materials = std::vector<MaterialEvaluation>;
  const auto breed = stage<Nothing, BreedInput, BreedRecord>("breed", 1, this)
                         .items(&Self::island_count)
                         .input(&Self::breeding_input)
                         .compute(&Self::breed)
                         .check(&Self::check_breed)
                         .blocks(&Self::breed_blocks)
                         .kept_through(&Self::kept_for_next_generation);
  const auto front = stage<Nothing, FrontInput, FrontRecord>("front", 1, this)
                         .items(&Self::one)
                         .input(&Self::front_input)
                         .compute(&Self::keep_front)
                         .blocks(&Self::front_blocks)
                         .kept_through(&Self::kept_for_next_generation);
  const auto evaluate = stage<EvaluationContext, Nothing, EvaluationRecord>("evaluate", 1, this)
                            .items(&Self::chunk_count)
                            .context(&Self::evaluation_context)
                            .compute(&Self::evaluate)
                            .check(&Self::check_evaluation)
                            .blocks(&Self::no_blocks)
                            .kept_through(&Self::kept_for_next_generation)
                            .fold(&Self::fold_evaluation);
  add_cycle(std::uint32_t(settings_.generations), {parts(breed, front), parts(evaluate)});
  add_stage(stage<Nothing, FrontInput, FrontRecord>("last front", 1, this)
                .items(&Self::one)
                .input(&Self::last_front_input)
                .compute(&Self::keep_last_front)
                .blocks(&Self::last_front_blocks)
                .kept_through(&Self::last_front_kept_through));
  if (!settings_.evaluation.enabled) return;
  add_stage(stage<Nothing, Trees, MaterialEvaluation>("materials", 1, this)
                .items(&Self::material_count)
                .input(&Self::material_input)
                .compute(&Self::evaluate_material)
                .check(&Self::check_material)
                .blocks(&Self::material_blocks)
                .kept_through(&Self::next_stage_reads)
                .fold(&Self::fold_material));
  add_stage(stage<Nothing, Materials, std::vector<AverageRow>>("averages", 1, this)
                .items(&Self::one)
                .input(&Self::averages_input)
                .compute(&Self::average)
                .blocks(&Self::averages_blocks));
}

std::uint32_t BrdfSearchWorkload::kept_for_next_generation(const StageItem& at) const {
  return stage_number("evaluate", at.step) + 1;
}

std::uint32_t BrdfSearchWorkload::last_front_kept_through(const StageItem& at) const {
  return settings_.evaluation.enabled ? stage_number("materials") : at.id.stage;
}

std::size_t BrdfSearchWorkload::evaluated_materials() const {
  return settings_.evaluation.training.size() + settings_.evaluation.testing.size();
}

// Fits trees chunk x item .. chunk x (item + 1) - 1 of the context's distinct trees.
EvaluationRecord BrdfSearchWorkload::evaluate(const Task<EvaluationContext, Nothing>& task) const {
  const auto& trees = task.context.trees;
  const std::size_t first = task.item() * settings_.chunk;
  const std::size_t last = std::min(trees.size(), first + settings_.chunk);
  EvaluationRecord record;
  for (std::size_t k = first; k < last; ++k) {
    const gp::SyntaxTree& tree = trees[k];
    const auto compiled = gp::compile(tree, brdf_parameter_count);
    CandidateScore score;
    if (compiled)
      score = score_candidate(*compiled, *settings_.data, settings_.fit, task.random(k - first), task.context.abandon_above);
    record.errors.push_back(score.error);
    record.sizes.push_back(double(tree.size()));
    score.material_errors.resize(settings_.data->materials(), gp::worst_error);
    record.material_errors.push_back(score.material_errors);
    record.abandoned.push_back(score.abandoned ? 1 : 0);
    if (task.stop_requested()) throw runtime::Cancelled();
  }
  return record;
}

void BrdfSearchWorkload::check_evaluation(const StageItem&, const EvaluationRecord& r) const {
  if (r.sizes.size() != r.errors.size() || r.material_errors.size() != r.errors.size() ||
      r.abandoned.size() != r.errors.size())
    throw RunError("a BRDF search evaluation record holds lists of different lengths");
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
