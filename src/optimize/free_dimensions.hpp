#pragma once
// The dimensions an optimizer may move: those with lower < upper.
#include <cstddef>
#include <vector>

#include "pbrfit/optimize/bounds.hpp"

namespace pbrfit::optimize::detail {

inline std::vector<std::size_t> free_dimensions(const Bounds& bounds) {
  std::vector<std::size_t> free;
  for (std::size_t d = 0; d < bounds.dimension(); ++d) {
    if (!bounds.is_fixed(d)) free.push_back(d);
  }
  return free;
}

}  // namespace pbrfit::optimize::detail
