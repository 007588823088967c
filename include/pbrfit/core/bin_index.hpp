#pragma once
// Which of `count` equal bins of [0, 1) a position falls in, clamped into the bins: positions <= 0 (and
// NaN) give bin 0, positions >= 1 the last bin. count >= 1.
#include <algorithm>
#include <cstddef>

namespace pbrfit {

inline std::size_t bin_index(double position, std::size_t count) {
  if (!(position > 0.0)) return 0;
  return std::min(static_cast<std::size_t>(position * static_cast<double>(count)), count - 1);
}

}  // namespace pbrfit
