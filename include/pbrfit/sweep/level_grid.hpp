#pragma once
// The cells of one level of a sweep: the product of its axes, numbered row-major (the first axis
// outermost, the last fastest), as the level's HDF5 tables store them.
//
// Invariants: every axis is valid (grid_axis.hpp); cell_count() is the product of the counts;
// flat_index(indices(c)) == c for every cell c.
#include <cstddef>
#include <span>
#include <vector>

#include "pbrfit/sweep/grid_axis.hpp"

namespace pbrfit::sweep {

class LevelGrid {
 public:
  // Throws std::invalid_argument for an invalid axis or no axes.
  explicit LevelGrid(std::vector<GridAxis> axes);

  const std::vector<GridAxis>& axes() const { return axes_; }
  std::size_t dimension() const { return axes_.size(); }
  std::size_t cell_count() const { return cell_count_; }

  std::vector<std::size_t> indices(std::size_t cell) const;
  std::size_t flat_index(std::span<const std::size_t> indices) const;
  // The axis values of a cell.
  std::vector<double> coordinates(std::size_t cell) const;

 private:
  std::vector<GridAxis> axes_;
  std::size_t cell_count_ = 1;
};

}  // namespace pbrfit::sweep
