#pragma once
// A hierarchical parameter sweep as a runtime workload (sweep/sweep_schedule.hpp): a stage per level (or
// per marching step of a level), an item per cell. A cell's item input is the fits of the cells that
// warm-start it, taken from the kept results of earlier stages; a fit is kept until the last stage that
// reads it. Each cell fits every model of the job against the problem's target for that cell.
//
// Result layout: a group `<model>/level<l>` per model and level, over the level's axes, with one table
// per parameter (role parameter), `error` (role error), `evaluations` (count), `start` (which start won,
// start_code_labels) and `global_search` (whether DE ran), and the model's outputs; a vector output has an
// extra innermost axis `<output>_component`. The last level is the requested grid.
//
// Projections (Pesce & Iwanicki 2015, section 4.2.2: fitted parameters averaged over incidence): with
// `projections`, a last stage has one item per projected axis, whose input is every fit of the last level;
// it writes `<model>/level<L>_mean_over_<axis>` over the other axes, with each parameter's and the error's
// mean and standard deviation over the projected axis.
#include <string>
#include <vector>

#include "pbrfit/jobs/sweep/cell_result.hpp"
#include "pbrfit/jobs/sweep/sweep_settings.hpp"
#include "pbrfit/runtime/workload.hpp"

namespace pbrfit::jobs::sweep {

class SweepWorkload final : public runtime::Workload {
 public:
  explicit SweepWorkload(SweepSettings settings);

  store::ResultLayout layout() const override;
  std::uint32_t stage_count() const override;
  std::uint64_t item_count(std::uint32_t stage) const override;
  Bytes item_input(std::uint32_t stage, std::uint64_t item, const ItemResults& kept) const override;
  Bytes compute(const runtime::ItemTask& task) const override;
  std::vector<store::Block> blocks(WorkItemId id, const Bytes& result) const override;
  std::uint32_t kept_through(WorkItemId id) const override;
  void fold_summary(Bytes& summary, WorkItemId id, const Bytes& result) const override;
  std::string headline(const Bytes& summary) const override;

  const pbrfit::sweep::SweepSchedule& schedule() const { return schedule_; }

 private:
  std::string group_name(std::size_t model, std::uint32_t level) const;
  store::Group level_group(std::size_t model, std::uint32_t level) const;
  // Projections (sweep_projection.cpp).
  bool is_projection(std::uint32_t stage) const { return stage == schedule_.stage_count(); }
  std::uint32_t final_level() const { return std::uint32_t(schedule_.levels().size() - 1); }
  std::string projection_name(std::size_t model, std::size_t projection) const;
  pbrfit::sweep::LevelGrid projected_grid(std::size_t projection) const;
  store::Group projection_group(std::size_t model, std::size_t projection) const;
  Bytes projection_input(const ItemResults& kept) const;
  Bytes project(const runtime::ItemTask& task) const;
  std::vector<store::Block> projection_blocks(WorkItemId id, const Bytes& result) const;

  SweepSettings settings_;
  std::vector<ModelInfo> models_;  // the job's models, in job order
  std::vector<FitShape> shapes_;
  pbrfit::sweep::SweepSchedule schedule_;
};

}  // namespace pbrfit::jobs::sweep
