#pragma once
// The order in which a hierarchical sweep fits its cells, as stages of independent cells for the runtime,
// and which earlier cells warm-start each cell (Pesce & Iwanicki 2015, section 3.3; Heitz et al. 2016).
//  - Each level is one stage, or, when marching along an axis, one stage per index of that axis (in
//    increasing order, or decreasing when `reverse`): a cell then warm-starts from its neighbour one step
//    back along the marching axis, which the stage before has fitted.
//  - A cell of level l > 0 also warm-starts from its nearest parent in level l - 1 (hierarchy.hpp).
//  - Cells of level 0 at the first marching step (or all of level 0 without marching) start cold.
// Within a stage, cells are listed by increasing flat index.
//
// Invariants: every cell of every level appears in exactly one stage; every source of a cell lies in an
// earlier stage; last_reader(c) >= stage_of(c) and no stage after last_reader(c) lists c as a source.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "pbrfit/sweep/level_grid.hpp"

namespace pbrfit::sweep {

struct CellRef {
  std::uint32_t level = 0;
  std::size_t cell = 0;
  bool operator==(const CellRef&) const = default;
};

struct Marching {
  std::size_t axis = 0;  // index into the level's axes
  bool reverse = false;
};

struct SweepStage {
  std::uint32_t level = 0;
  std::vector<std::size_t> cells;
};

class SweepSchedule {
 public:
  // Throws std::invalid_argument for no levels or a marching axis out of range.
  SweepSchedule(std::vector<LevelGrid> levels, std::optional<Marching> marching);

  const std::vector<LevelGrid>& levels() const { return levels_; }
  const std::vector<SweepStage>& stages() const { return stages_; }
  std::uint32_t stage_count() const { return std::uint32_t(stages_.size()); }
  CellRef cell_of(std::uint32_t stage, std::size_t item) const { return {stages_[stage].level, stages_[stage].cells[item]}; }

  // The cells whose fits warm-start this one: the marching neighbour first, then the parent.
  std::vector<CellRef> sources(const CellRef& cell) const;
  std::uint32_t stage_of(const CellRef& cell) const;
  std::size_t item_of(const CellRef& cell) const;
  // The last stage that reads this cell's fit as a warm start (its own stage when none does).
  std::uint32_t last_reader(const CellRef& cell) const;

 private:
  std::size_t offset(const CellRef& cell) const { return level_offsets_[cell.level] + cell.cell; }
  std::size_t march_index(const CellRef& cell) const;
  void add_level_stages(std::uint32_t level);

  std::vector<LevelGrid> levels_;
  std::optional<Marching> marching_;
  std::vector<SweepStage> stages_;
  std::vector<std::size_t> level_offsets_;  // flat position of each level's first cell over all levels
  std::vector<std::uint32_t> stage_;        // per cell over all levels
  std::vector<std::size_t> item_;
  std::vector<std::uint32_t> last_reader_;
};

}  // namespace pbrfit::sweep
