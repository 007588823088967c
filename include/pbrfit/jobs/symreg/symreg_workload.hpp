#pragma once
// Symbolic regression as a runtime workload: island-model linear GP (gp/evolve.hpp) with a ring of
// `islands` islands per output. Its plan: `epochs` stages of migration epochs, then `fronts`, one stage.
// Step e of `epochs` is migration epoch e: item output * islands + island
// evolves that island for migration_interval generations from its state of epoch e - 1 (its item input,
// with the best `migrants` of the island before it on the ring, picked on rank 0). The last stage has one
// item: it merges every island's front into each output's Pareto front, measures it, compares it with
// the anchors and lists the sub-expressions that recur across the fronts.
//
// Result layout (docs/results-symreg.md): per output a group `<output>` with growing record tables `front`,
// `archive` (every program that entered an island's non-dominated set), `log` (a row per island and epoch),
// `anchors` and `knee_prediction`; a group `subexpressions` with `recurring`.
#include <string>
#include <vector>

#include "pbrfit/jobs/symreg/island_epoch.hpp"
#include "pbrfit/jobs/symreg/symreg_settings.hpp"
#include "pbrfit/runtime/staged_workload.hpp"
#include "pbrfit/store/block_codec.hpp"

namespace pbrfit::jobs::symreg {

// The running summary (symreg_summary.cpp), in the style of PySR's progress lines.
struct SymregSummary {
  static constexpr std::size_t outputs = 4;
  static constexpr std::size_t cost_buckets = 64;  // cost rounded to an integer, the last bucket holding the rest
  std::uint64_t evaluations = 0;
  std::uint64_t generation = 0;
  std::uint64_t seen[outputs] = {};  // bit b: bucket b holds an error
  double best[outputs][cost_buckets] = {};
};

class SymregWorkload final : public runtime::StagedWorkload<SymregSummary> {
 public:
  explicit SymregWorkload(SymregSettings settings);

  store::ResultLayout layout() const override;
  // Once every output has an island at the target error, the remaining epochs are skipped.
  std::uint32_t next_stage(std::uint32_t completed, const ItemResults& kept) const override;
  std::string work_unit() const override { return "evaluations"; }

 private:
  // The fronts stage's input: every island's front (gp::archive_to_bytes) after the last epoch run.
  using IslandFronts = std::vector<Bytes>;
  // Its result: the blocks of the fronts, encoded by codec_ (they are all it writes).
  using FrontBlocks = Bytes;
  using StageItem = runtime::StageItem;

  // Epochs (symreg_workload.cpp).
  std::uint64_t island_count(std::uint32_t) const { return settings_.islands * settings_.data->outputs.size(); }
  EpochInput epoch_input(std::uint32_t step, std::uint64_t item, const runtime::KeptResults& kept) const;
  EpochResult evolve_island(const runtime::StageTask<Nothing, EpochInput>& task) const;
  void check_epoch(const StageItem& at, const EpochResult& epoch) const;
  std::vector<store::Block> epoch_blocks(const StageItem& at, const EpochResult& epoch) const;  // symreg_layout.cpp
  std::uint32_t epoch_kept_through(const StageItem& at) const { return at.id.stage + 1; }
  void fold_epoch(Summary& summary, const StageItem& at, const EpochResult& epoch) const;  // symreg_summary.cpp
  std::string headline_of(const Summary& summary) const override;
  double work_done_in(const Summary& summary) const override { return double(summary.evaluations); }
  bool output_solved(std::uint32_t stage, std::size_t output, const runtime::KeptResults& kept) const;

  // Fronts (symreg_final.cpp).
  std::uint64_t one(std::uint32_t) const { return 1; }
  IslandFronts island_fronts(std::uint32_t step, std::uint64_t item, const runtime::KeptResults& kept) const;
  FrontBlocks final_fronts(const runtime::StageTask<Nothing, IslandFronts>& task) const;
  std::vector<store::Block> front_blocks(const StageItem& at, const FrontBlocks& encoded) const;  // symreg_layout.cpp

  std::size_t output_of(std::uint64_t item) const { return item / settings_.islands; }
  std::size_t input_count(std::size_t output) const { return settings_.data->outputs[output].inputs.size(); }
  const gp::EvolveOptions& options(std::size_t output) const { return options_[output]; }
  store::Group output_group(std::size_t output) const;

  SymregSettings settings_;
  std::vector<gp::EvolveOptions> options_;  // per output (its input count)
  store::BlockCodec codec_;
};

}  // namespace pbrfit::jobs::symreg
