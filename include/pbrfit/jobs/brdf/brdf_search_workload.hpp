#pragma once
// The genBRDF search (Brady et al., sections 3.2 and 4) as a runtime workload. Its plan, with G generations:
//  - a cycle of G generations, each two stages:
//    - `breed` and `front`: breed item i < islands breeds island i's next genomes (gp/edit_evolution.hpp)
//      from its evaluated members of the generation before, after the best `migrants` of island i - 1 on
//      the ring replaced its worst members (every migration_interval generations), and reifies them into
//      trees; generation 0 is one random edit per genome. The one `front` item keeps the Pareto front of
//      error vs tree size: the front so far merged with the generation before;
//    - `evaluate`: the distinct trees of the generation (the stage context, in order of first appearance
//      over the islands' slots), `chunk` per item whatever the islands, so every core works; each compiled
//      and fitted to every training material and channel (candidate_score.hpp), abandoned once worse than
//      the worst island median of the generation before (`abandon_poor`). Items past the distinct trees
//      have nothing to do;
//  - `last front`: the front after the last generation, whose knee is simplified by culling
//    sub-expressions that do not raise the error;
//  - when evaluating, `materials`: an item per training then testing material fits the seed and the chosen
//    front members to it, renders the measured material and every fit and compares the images
//    (material_evaluation.hpp); then `averages`: one item averages them per material set.
// A result is kept only until the stage that reads it is done.
//
// Result layout (docs/results-brdf_search.md): group `brdf` with growing record tables `front`, `archive`
// (every tree that entered the front), `log` (a row per island and generation) and `simplified`; group
// `brdf/evaluation` with `materials`, `averages` and the `renders`.
#include <limits>
#include <string>
#include <vector>

#include "pbrfit/jobs/brdf/brdf_search_settings.hpp"
#include "pbrfit/jobs/brdf/material_evaluation.hpp"
#include "pbrfit/jobs/brdf/tree_bytes.hpp"
#include "pbrfit/runtime/staged_workload.hpp"

namespace pbrfit::jobs::brdf {

struct BreedInput;  // search_records.hpp
struct BreedRecord;
struct EvaluationContext;
struct EvaluationRecord;
struct FrontInput;
struct FrontRecord;
struct AverageRow;

// The running summary (search_summary.cpp): counts, sums and minima, folded in any order.
struct BrdfSearchSummary {
  std::uint64_t evaluated = 0;   // genomes
  std::uint64_t generation = 0;  // highest generation evaluated, plus one
  double best = std::numeric_limits<double>::infinity();
  double best_size = 0.0;
  std::uint64_t materials = 0;  // evaluated after the search
};

class BrdfSearchWorkload final : public runtime::StagedWorkload<BrdfSearchSummary> {
 public:
  explicit BrdfSearchWorkload(BrdfSearchSettings settings);

  store::ResultLayout layout() const override;
  std::string work_unit() const override { return "fits"; }

  // A member of one generation: genome, tree, error and tree size, in slot order of all islands.
  struct Evaluated {
    gp::Genome genome;
    gp::SyntaxTree tree{{gp::SyntaxNode{}}};
    double error = gp::worst_error;
    double size = 0.0;
    bool abandoned = false;  // the error is a lower bound (candidate_score.hpp)
  };

 private:
  using StageItem = runtime::StageItem;
  template <class Context, class Input>
  using Task = runtime::StageTask<Context, Input>;
  using Kept = runtime::KeptResults;

  std::size_t members() const { return settings_.islands * settings_.population; }
  std::size_t chunks() const { return (members() + settings_.chunk - 1) / settings_.chunk; }
  std::uint64_t island_count(std::uint32_t) const { return settings_.islands; }
  std::uint64_t chunk_count(std::uint32_t) const { return chunks(); }
  std::uint64_t one(std::uint32_t) const { return 1; }
  std::uint64_t material_count(std::uint32_t) const { return evaluated_materials(); }
  // Every result of a generation is read by the next generation's first stage (or the last front).
  std::uint32_t kept_for_next_generation(const StageItem& at) const;
  std::uint32_t last_front_kept_through(const StageItem& at) const;
  std::uint32_t next_stage_reads(const StageItem& at) const { return at.id.stage + 1; }
  double abandon_threshold(std::uint32_t generation, const Kept& kept) const;
  std::size_t evaluated_materials() const;
  std::string evaluated_material(std::uint64_t item) const;  // training, then testing
  std::vector<std::string> model_names() const;
  // The seed, the references, then the chosen members of the last front (the seed again for each when the
  // front is empty).
  std::vector<ScoredTree> evaluated_models(const FrontRecord& record) const;

  // The bred members of a generation, without errors (search_generation.cpp).
  std::vector<Evaluated> bred_members(std::uint32_t generation, const Kept& kept) const;
  // The members of a generation with the errors of their evaluation.
  std::vector<Evaluated> generation_members(std::uint32_t generation, const Kept& kept) const;
  EvaluationContext evaluation_context(std::uint32_t generation, const Kept& kept) const;
  EvaluationRecord evaluate(const Task<EvaluationContext, Nothing>& task) const;  // brdf_search_workload.cpp
  void check_evaluation(const StageItem& at, const EvaluationRecord& record) const;
  std::vector<store::Block> no_blocks(const StageItem&, const EvaluationRecord&) const { return {}; }

  // Breeding (search_breeding.cpp).
  BreedInput breeding_input(std::uint32_t generation, std::uint64_t island, const Kept& kept) const;
  BreedRecord breed(const Task<Nothing, BreedInput>& task) const;
  void check_breed(const StageItem& at, const BreedRecord& record) const;
  BreedRecord& with_trees(BreedRecord& record) const;
  std::vector<store::Block> breed_blocks(const StageItem& at, const BreedRecord& record) const;  // search_blocks.cpp

  // The front (search_front.cpp, search_blocks.cpp).
  FrontInput front_input(std::uint32_t generation, std::uint64_t, const Kept& kept) const;
  FrontInput last_front_input(std::uint32_t, std::uint64_t, const Kept& kept) const;
  FrontRecord keep_front(const Task<Nothing, FrontInput>& task) const;
  FrontRecord keep_last_front(const Task<Nothing, FrontInput>& task) const;
  std::vector<store::Block> front_blocks(const StageItem& at, const FrontRecord& record) const;
  std::vector<store::Block> last_front_blocks(const StageItem& at, const FrontRecord& record) const;
  ScoredTree cull(const ScoredTree& knee, const Task<Nothing, FrontInput>& task) const;

  // The evaluation after the search (search_evaluation.cpp, evaluation_layout.cpp).
  std::vector<gp::SyntaxTree> material_input(std::uint32_t, std::uint64_t, const Kept& kept) const;
  MaterialEvaluation evaluate_material(const Task<Nothing, std::vector<gp::SyntaxTree>>& task) const;
  void check_material(const StageItem& at, const MaterialEvaluation& record) const;
  std::vector<store::Block> material_blocks(const StageItem& at, const MaterialEvaluation& record) const;
  std::vector<MaterialEvaluation> averages_input(std::uint32_t, std::uint64_t, const Kept& kept) const;
  std::vector<AverageRow> average(const Task<Nothing, std::vector<MaterialEvaluation>>& task) const;
  std::vector<store::Block> averages_blocks(const StageItem& at, const std::vector<AverageRow>& rows) const;

  // The summary (search_summary.cpp).
  void fold_evaluation(Summary& summary, const StageItem& at, const EvaluationRecord& record) const;
  void fold_material(Summary& summary, const StageItem& at, const MaterialEvaluation& record) const;
  std::string headline_of(const Summary& summary) const override;
  double work_done_in(const Summary& summary) const override;

  store::Group evaluation_group() const;
  store::Block models_block(const FrontRecord& record) const;
  std::string expression(const gp::SyntaxTree& tree) const;

  BrdfSearchSettings settings_;
};

}  // namespace pbrfit::jobs::brdf
