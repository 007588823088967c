#pragma once
// Symbolic regression as a runtime workload: island-model linear GP (gp/evolve.hpp) with a ring of
// `islands` islands per output. Stage e < epochs() is migration epoch e: item output * islands + island
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
#include "pbrfit/runtime/workload.hpp"
#include "pbrfit/store/block_codec.hpp"

namespace pbrfit::jobs::symreg {

class SymregWorkload final : public runtime::Workload {
 public:
  explicit SymregWorkload(SymregSettings settings);

  store::ResultLayout layout() const override;
  std::uint32_t stage_count() const override { return std::uint32_t(settings_.epochs() + 1); }
  std::uint64_t item_count(std::uint32_t stage) const override;
  Bytes item_input(std::uint32_t stage, std::uint64_t item, const ItemResults& kept) const override;
  Bytes compute(const runtime::ItemTask& task) const override;
  std::vector<store::Block> blocks(WorkItemId id, const Bytes& result) const override;
  std::uint32_t kept_through(WorkItemId id) const override;
  // Once every output has an island at the target error, the remaining epochs are skipped.
  std::uint32_t next_stage(std::uint32_t completed, const ItemResults& kept) const override;
  void fold_summary(Bytes& summary, WorkItemId id, const Bytes& result) const override;
  std::string headline(const Bytes& summary) const override;
  double work_done(const Bytes& summary) const override;
  std::string work_unit() const override { return "evaluations"; }

 private:
  bool is_final(std::uint32_t stage) const { return stage == settings_.epochs(); }
  std::size_t output_of(std::uint64_t item) const { return item / settings_.islands; }
  std::size_t input_count(std::size_t output) const { return settings_.data->outputs[output].inputs.size(); }
  const gp::EvolveOptions& options(std::size_t output) const { return options_[output]; }
  Bytes evolve_island(const runtime::ItemTask& task) const;
  Bytes final_fronts(const runtime::ItemTask& task) const;
  std::vector<store::Block> epoch_blocks(WorkItemId id, const EpochRecord& epoch) const;
  store::Group output_group(std::size_t output) const;

  SymregSettings settings_;
  std::vector<gp::EvolveOptions> options_;  // per output (its input count)
  store::BlockCodec codec_;
};

}  // namespace pbrfit::jobs::symreg
