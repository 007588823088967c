#pragma once
// Implementation of integrate_adaptive; included at the end of adaptive_cubature.hpp.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

#include "pbrfit/integrate/adaptive_cubature.hpp"
#include "pbrfit/integrate/compensated_sum.hpp"
#include "pbrfit/integrate/tensor_gauss_kronrod.hpp"

namespace pbrfit::integrate {
namespace adaptive_detail {

template <int Dim, int Comp>
struct Tile {
  Box<Dim> box;
  TileEstimate<Comp> estimate;
  int depth = 0;     // number of splits from an initial tile
  bool leaf = true;  // false once split
};

template <int Dim>
std::array<Box<Dim>, 2> halves(const Box<Dim>& box, int axis) {
  const double middle = 0.5 * (box.lo[axis] + box.hi[axis]);
  std::array<Box<Dim>, 2> children{box, box};
  children[0].hi[axis] = middle;
  children[1].lo[axis] = middle;
  return children;
}

// All tiles ever created (index = creation order), the heap of splittable leaves, and the running
// sums of leaf errors and values. Invariant: finite_error_sum + (infinite_error_leaves ? inf : 0) equals the
// sum of the leaf error estimates up to rounding drift, which resynchronize() removes (and likewise the
// value sums).
template <int Dim, int Comp>
class TileSet {
 public:
  explicit TileSet(int max_depth) : max_depth_(max_depth) {}

  void add(const Box<Dim>& box, const TileEstimate<Comp>& estimate, int depth) {
    TileEstimate<Comp> sanitized = estimate;
    if (!std::isfinite(sanitized.error)) sanitized.error = std::numeric_limits<double>::infinity();
    tiles_.push_back(Tile<Dim, Comp>{box, sanitized, depth, true});
    count_error(sanitized.error, +1);
    for (int c = 0; c < Comp; ++c) value_sum_[c] += sanitized.value[c];
    if (depth < max_depth_) {
      heap_.push_back(tiles_.size() - 1);
      std::push_heap(heap_.begin(), heap_.end(), heap_order());
    }
  }

  bool has_splittable() const { return !heap_.empty(); }

  // Removes the worst splittable leaf from the leaves and returns a copy of it.
  Tile<Dim, Comp> take_worst() {
    std::pop_heap(heap_.begin(), heap_.end(), heap_order());
    Tile<Dim, Comp>& worst = tiles_[heap_.back()];
    heap_.pop_back();
    worst.leaf = false;
    count_error(worst.estimate.error, -1);
    for (int c = 0; c < Comp; ++c) value_sum_[c] -= worst.estimate.value[c];
    return worst;
  }

  // max(abs_tolerance, rel_tolerance * the largest |running value|).
  double tolerance(const AdaptiveOptions& options) const {
    if (!(options.rel_tolerance > 0.0)) return options.abs_tolerance;
    double magnitude = 0.0;
    for (int c = 0; c < Comp; ++c) magnitude = std::max(magnitude, std::abs(value_sum_[c]));
    return std::max(options.abs_tolerance, options.rel_tolerance * magnitude);
  }

  bool below(double tolerance) const { return infinite_error_leaves_ == 0 && finite_error_sum_ <= tolerance; }

  // Replaces the running sum by the compensated sum over the leaves (removes drift).
  void resynchronize() {
    CompensatedSum sum;
    std::array<CompensatedSum, Comp> values{};
    for (const auto& tile : tiles_) {
      if (!tile.leaf) continue;
      if (std::isfinite(tile.estimate.error)) sum.add(tile.estimate.error);
      for (int c = 0; c < Comp; ++c) values[c].add(tile.estimate.value[c]);
    }
    finite_error_sum_ = sum.value();
    for (int c = 0; c < Comp; ++c) value_sum_[c] = values[c].value();
  }

  AdaptiveResult<Comp> result(double tolerance) const {
    std::array<CompensatedSum, Comp> values{};
    CompensatedSum error;
    AdaptiveResult<Comp> out;
    for (const auto& tile : tiles_) {
      if (!tile.leaf) continue;
      for (int c = 0; c < Comp; ++c) values[c].add(tile.estimate.value[c]);
      error.add(tile.estimate.error);
      ++out.tiles;
    }
    for (int c = 0; c < Comp; ++c) out.value[c] = values[c].value();
    out.error_estimate = error.value();
    out.converged = out.error_estimate <= tolerance;
    return out;
  }

 private:
  // "a before b in a max-heap": lower error first, and among equal errors the later-created tile,
  // so the heap top is the largest error with the earliest creation index.
  auto heap_order() const {
    return [this](std::size_t a, std::size_t b) {
      const double ea = tiles_[a].estimate.error;
      const double eb = tiles_[b].estimate.error;
      return ea < eb || (ea == eb && a > b);
    };
  }

  void count_error(double error, int sign) {
    if (std::isinf(error)) {
      infinite_error_leaves_ += sign;
    } else {
      finite_error_sum_ += sign * error;
    }
  }

  int max_depth_;
  std::vector<Tile<Dim, Comp>> tiles_;
  std::vector<std::size_t> heap_;  // indices into tiles_ of leaves with depth < max_depth
  double finite_error_sum_ = 0.0;
  int infinite_error_leaves_ = 0;
  std::array<double, Comp> value_sum_{};
};

}  // namespace adaptive_detail

template <int Dim, int Comp, class Integrand>
AdaptiveResult<Comp> integrate_adaptive(const Integrand& f, std::span<const Box<Dim>> initial_tiles,
                                        const AdaptiveOptions& options) {
  using Rule = TensorGaussKronrod<Dim, Comp>;
  constexpr std::size_t points = Rule::points_per_tile();
  Rule rule;
  adaptive_detail::TileSet<Dim, Comp> tiles(options.max_depth);
  std::size_t evaluations = 0;

  for (const Box<Dim>& box : initial_tiles) {
    tiles.add(box, rule.estimate(f, box), 0);
    evaluations += points;
  }

  while (true) {
    if (tiles.below(tiles.tolerance(options))) {
      tiles.resynchronize();
      if (tiles.below(tiles.tolerance(options))) break;
    }
    if (!tiles.has_splittable()) break;
    if (evaluations + 2 * points > options.max_evaluations) break;
    const auto worst = tiles.take_worst();
    for (const Box<Dim>& child : adaptive_detail::halves(worst.box, worst.estimate.split_dimension)) {
      tiles.add(child, rule.estimate(f, child), worst.depth + 1);
    }
    evaluations += 2 * points;
  }

  AdaptiveResult<Comp> result = tiles.result(tiles.tolerance(options));
  result.evaluations = evaluations;
  return result;
}

}  // namespace pbrfit::integrate
