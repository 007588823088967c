#pragma once
// Orders indices by increasing value, ties in index order, without allocating once `order` has its size:
// an insertion sort, fast for the small and nearly sorted sets (simplex vertices, DE populations) it
// serves. Values are never NaN (the evaluator reports NaN as +inf).
#include <cstddef>
#include <numeric>
#include <span>
#include <vector>

namespace pbrfit::optimize::detail {

inline void order_by_value(std::span<const double> values, std::vector<std::size_t>& order) {
  order.resize(values.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  for (std::size_t i = 1; i < order.size(); ++i) {
    const std::size_t moving = order[i];
    std::size_t j = i;
    for (; j > 0 && values[moving] < values[order[j - 1]]; --j) order[j] = order[j - 1];
    order[j] = moving;
  }
}

}  // namespace pbrfit::optimize::detail
