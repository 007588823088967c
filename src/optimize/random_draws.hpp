#pragma once
// Draws the optimizers make from a RandomStream. Each consumes a fixed count of numbers from the stream,
// so a run's sequence of draws, and hence its result, is a function of the stream's starting state.
#include <algorithm>
#include <cstddef>

#include "pbrfit/core/random_stream.hpp"

namespace pbrfit::optimize::detail {

// Uniform in [0, n) for n > 0 (one number).
inline std::size_t index_below(RandomStream& random, std::size_t n) {
  return std::min(n - 1, static_cast<std::size_t>(random.uniform() * static_cast<double>(n)));
}

// Uniform in [lower, upper] (one number).
inline double uniform_in(RandomStream& random, double lower, double upper) {
  return lower + (upper - lower) * random.uniform();
}

}  // namespace pbrfit::optimize::detail
