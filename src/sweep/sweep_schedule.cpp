#include "pbrfit/sweep/sweep_schedule.hpp"

#include <algorithm>
#include <stdexcept>

#include "pbrfit/sweep/hierarchy.hpp"

namespace pbrfit::sweep {

SweepSchedule::SweepSchedule(std::vector<LevelGrid> levels, std::optional<Marching> marching)
    : levels_(std::move(levels)), marching_(marching) {
  if (levels_.empty()) throw std::invalid_argument("sweep: a schedule needs at least one level");
  if (marching_ && marching_->axis >= levels_.front().dimension())
    throw std::invalid_argument("sweep: the marching axis is not an axis of the grid");
  std::size_t total = 0;
  for (const auto& level : levels_) {
    level_offsets_.push_back(total);
    total += level.cell_count();
  }
  stage_.resize(total);
  item_.resize(total);
  for (std::uint32_t l = 0; l < levels_.size(); ++l) add_level_stages(l);
  last_reader_ = stage_;
  for (std::uint32_t s = 0; s < stages_.size(); ++s)
    for (std::size_t c : stages_[s].cells)
      for (const CellRef& source : sources({stages_[s].level, c}))
        last_reader_[offset(source)] = std::max(last_reader_[offset(source)], s);
}

std::size_t SweepSchedule::march_index(const CellRef& cell) const {
  const auto& grid = levels_[cell.level];
  const std::size_t index = grid.indices(cell.cell)[marching_->axis];
  return marching_->reverse ? grid.axes()[marching_->axis].count - 1 - index : index;
}

void SweepSchedule::add_level_stages(std::uint32_t level) {
  const auto& grid = levels_[level];
  const std::size_t steps = marching_ ? grid.axes()[marching_->axis].count : 1;
  const std::uint32_t first = stage_count();
  for (std::size_t k = 0; k < steps; ++k) stages_.push_back({level, {}});
  for (std::size_t c = 0; c < grid.cell_count(); ++c) {
    const std::size_t step = marching_ ? march_index({level, c}) : 0;
    auto& stage = stages_[first + step];
    stage_[offset({level, c})] = first + std::uint32_t(step);
    item_[offset({level, c})] = stage.cells.size();
    stage.cells.push_back(c);
  }
}

std::vector<CellRef> SweepSchedule::sources(const CellRef& cell) const {
  std::vector<CellRef> out;
  const auto& grid = levels_[cell.level];
  if (marching_ && march_index(cell) > 0) {
    auto at = grid.indices(cell.cell);
    std::size_t& step = at[marching_->axis];
    step = marching_->reverse ? step + 1 : step - 1;  // one step back in marching order (march_index > 0)
    out.push_back({cell.level, grid.flat_index(at)});
  }
  if (cell.level > 0) out.push_back({cell.level - 1, nearest_parent(grid, cell.cell, levels_[cell.level - 1])});
  return out;
}

std::uint32_t SweepSchedule::stage_of(const CellRef& cell) const { return stage_[offset(cell)]; }
std::size_t SweepSchedule::item_of(const CellRef& cell) const { return item_[offset(cell)]; }
std::uint32_t SweepSchedule::last_reader(const CellRef& cell) const { return last_reader_[offset(cell)]; }

}  // namespace pbrfit::sweep
