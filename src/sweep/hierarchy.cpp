#include "pbrfit/sweep/hierarchy.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace pbrfit::sweep {
namespace {

std::size_t halved(const GridAxis& axis) {
  if (axis.count <= 1) return axis.count;
  // edges: ceil((n - 1) / 2) = floor(n / 2) intervals, at least one.
  if (axis.placement == Placement::edges) return std::max<std::size_t>(axis.count / 2, 1) + 1;
  return (axis.count + 1) / 2;
}

std::vector<GridAxis> coarser(const std::vector<GridAxis>& axes) {
  std::vector<GridAxis> out;
  for (const auto& axis : axes) out.push_back(axis.with_count(halved(axis)));
  return out;
}

bool same_counts(const std::vector<GridAxis>& a, const std::vector<GridAxis>& b) {
  for (std::size_t d = 0; d < a.size(); ++d)
    if (a[d].count != b[d].count) return false;
  return true;
}

// The first index whose node is nearest to value (ties to the lower index), in O(log n). An axis's nodes
// never decrease (grid_axis.hpp), so the distance falls, then rises: k, the first node at or past value,
// or k - 1 is nearest, then moved left over nodes exactly as near. The same index as a scan of every
// node, which made a fine level of n cells cost n^2 / 2 (minutes at 2^20).
std::size_t nearest_index(const GridAxis& coarse, double value) {
  // k: the first node at or past value, by bisection (clang 14 cannot compile libstdc++ 12's iota_view,
  // so std::ranges::partition_point over the indices is out of reach of the sanitizer builds).
  std::size_t k = 0;
  for (std::size_t count = coarse.count; count > 0;) {
    const std::size_t half = count / 2;
    if (coarse.value(k + half) < value) {
      k += half + 1;
      count -= half + 1;
    } else {
      count = half;
    }
  }
  const auto distance = [&](std::size_t j) { return std::abs(coarse.value(j) - value); };
  std::size_t best = std::min(k, coarse.count - 1);
  if (k > 0 && distance(k - 1) <= distance(best)) best = k - 1;
  while (best > 0 && distance(best - 1) == distance(best)) --best;
  return best;
}

}  // namespace

std::size_t max_level_count(const std::vector<GridAxis>& finest) {
  std::size_t levels = 1;
  for (auto axes = finest, next = coarser(axes); !same_counts(axes, next); axes = next, next = coarser(axes)) ++levels;
  return levels;
}

std::vector<LevelGrid> hierarchy(const std::vector<GridAxis>& finest, std::size_t level_count) {
  const std::size_t possible = max_level_count(finest);
  if (level_count < 1 || level_count > possible)
    throw std::invalid_argument("sweep: this grid allows 1 to " + std::to_string(possible) + " levels, not " +
                                std::to_string(level_count));
  std::vector<std::vector<GridAxis>> axes{finest};
  while (axes.size() < level_count) axes.insert(axes.begin(), coarser(axes.front()));
  std::vector<LevelGrid> levels;
  for (auto& level : axes) levels.emplace_back(std::move(level));
  return levels;
}

std::size_t nearest_parent(const LevelGrid& fine, std::size_t cell, const LevelGrid& coarse) {
  const auto at = fine.indices(cell);
  std::vector<std::size_t> parent(at.size());
  for (std::size_t d = 0; d < at.size(); ++d)
    parent[d] = nearest_index(coarse.axes()[d], fine.axes()[d].value(at[d]));
  return coarse.flat_index(parent);
}

}  // namespace pbrfit::sweep
