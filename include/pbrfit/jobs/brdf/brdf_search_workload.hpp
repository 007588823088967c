#pragma once
// The genBRDF search (Brady et al., sections 3.2 and 4) as a runtime workload. With G generations:
//  - stage 2g, breeding: item i < islands breeds island i's next genomes (gp/edit_evolution.hpp) from its
//    evaluated members of generation g - 1, after the best `migrants` of island i - 1 on the ring replaced
//    its worst members (every migration_interval generations), and reifies them into trees; generation 0
//    is one random edit per genome. The last item keeps the Pareto front of error vs tree size: the front
//    so far merged with generation g - 1;
//  - stage 2g + 1, evaluation: the distinct trees of generation g (the stage context, in order of first
//    appearance over the islands' slots), `chunk` per item whatever the islands, so every core works; each
//    compiled and fitted to every training material and channel (candidate_score.hpp), abandoned once
//    worse than the worst island median of generation g - 1 (`abandon_poor`; the context's first value).
//    Items past the distinct trees have nothing to do;
//  - stage 2G: the last front, whose knee is simplified by culling sub-expressions that do not raise the
//    error;
//  - stage 2G + 1 (when evaluating): an item per training then testing material fits the seed and the
//    chosen front members to it, renders the measured material and every fit and compares the images
//    (material_evaluation.hpp); stage 2G + 2: one item averages them per material set.
// A result is kept only until the stage that reads it is done.
//
// Result layout (docs/results-brdf_search.md): group `brdf` with growing record tables `front`, `archive`
// (every tree that entered the front), `log` (a row per island and generation) and `simplified`; group
// `brdf/evaluation` with `materials`, `averages` and the `renders`.
#include <string>
#include <vector>

#include "pbrfit/jobs/brdf/brdf_search_settings.hpp"
#include "pbrfit/jobs/brdf/tree_bytes.hpp"
#include "pbrfit/runtime/workload.hpp"

namespace pbrfit::jobs::brdf {

struct BreedRecord;  // search_records.hpp
struct FrontRecord;

class BrdfSearchWorkload final : public runtime::Workload {
 public:
  explicit BrdfSearchWorkload(BrdfSearchSettings settings);

  store::ResultLayout layout() const override;
  std::uint32_t stage_count() const override;
  std::uint64_t item_count(std::uint32_t stage) const override;
  Bytes stage_context(std::uint32_t stage, const ItemResults& kept) const override;
  Bytes item_input(std::uint32_t stage, std::uint64_t item, const ItemResults& kept) const override;
  Bytes compute(const runtime::ItemTask& task) const override;
  std::vector<store::Block> blocks(WorkItemId id, const Bytes& result) const override;
  std::uint32_t kept_through(WorkItemId id) const override;
  void fold_summary(Bytes& summary, WorkItemId id, const Bytes& result) const override;
  std::string headline(const Bytes& summary) const override;
  double work_done(const Bytes& summary) const override;
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
  enum class Role { breeding, front, evaluation, material, averages };
  Role role(WorkItemId id) const;
  std::uint32_t front_stage() const { return std::uint32_t(2 * settings_.generations); }
  std::uint32_t generation_of(std::uint32_t stage) const { return stage / 2; }
  std::size_t members() const { return settings_.islands * settings_.population; }
  std::size_t chunks() const { return (members() + settings_.chunk - 1) / settings_.chunk; }
  double abandon_threshold(std::uint32_t breeding_stage, const ItemResults& kept) const;
  std::size_t evaluated_materials() const;
  std::string evaluated_material(std::uint64_t item) const;  // training, then testing
  std::vector<std::string> model_names() const;
  // The seed, the references, then the chosen members of the last front (the seed again for each when the
  // front is empty).
  std::vector<ScoredTree> evaluated_models(const FrontRecord& record) const;

  // The bred members of the generation bred at `breeding_stage`, without errors; and the distinct trees.
  std::vector<Evaluated> bred_members(std::uint32_t breeding_stage, const ItemResults& kept) const;
  // The members of the generation bred at breeding_stage - 2, with the errors of their evaluation.
  std::vector<Evaluated> generation_members(std::uint32_t breeding_stage, const ItemResults& kept) const;
  Bytes breeding_input(std::uint32_t stage, std::uint64_t island, const ItemResults& kept) const;
  Bytes front_input(std::uint32_t stage, const ItemResults& kept) const;
  Bytes material_input(const ItemResults& kept) const;
  Bytes averages_input(const ItemResults& kept) const;
  Bytes breed(const runtime::ItemTask& task) const;
  BreedRecord& with_trees(BreedRecord& record) const;
  Bytes evaluate(const runtime::ItemTask& task) const;
  Bytes keep_front(const runtime::ItemTask& task) const;
  Bytes evaluate_material(const runtime::ItemTask& task) const;
  Bytes average(const runtime::ItemTask& task) const;
  std::vector<store::Block> front_blocks(WorkItemId id, const Bytes& result) const;
  std::vector<store::Block> evaluation_blocks(WorkItemId id, const Bytes& result) const;
  store::Group evaluation_group() const;
  store::Block models_block(const FrontRecord& record) const;
  std::string expression(const gp::SyntaxTree& tree) const;
  ScoredTree cull(const ScoredTree& knee, const runtime::ItemTask& task) const;

  BrdfSearchSettings settings_;
};

}  // namespace pbrfit::jobs::brdf
