#include "pbrfit/sweep/level_grid.hpp"

#include <stdexcept>

namespace pbrfit::sweep {

LevelGrid::LevelGrid(std::vector<GridAxis> axes) : axes_(std::move(axes)) {
  if (axes_.empty()) throw std::invalid_argument("sweep: a grid needs at least one axis");
  for (const auto& axis : axes_) {
    validate(axis);
    cell_count_ *= axis.count;
  }
}

std::vector<std::size_t> LevelGrid::indices(std::size_t cell) const {
  std::vector<std::size_t> out(axes_.size());
  for (std::size_t d = axes_.size(); d-- > 0;) {
    out[d] = cell % axes_[d].count;
    cell /= axes_[d].count;
  }
  return out;
}

std::size_t LevelGrid::flat_index(std::span<const std::size_t> indices) const {
  std::size_t cell = 0;
  for (std::size_t d = 0; d < axes_.size(); ++d) cell = cell * axes_[d].count + indices[d];
  return cell;
}

std::vector<double> LevelGrid::coordinates(std::size_t cell) const {
  const auto at = indices(cell);
  std::vector<double> out(axes_.size());
  for (std::size_t d = 0; d < axes_.size(); ++d) out[d] = axes_[d].value(at[d]);
  return out;
}

}  // namespace pbrfit::sweep
