#pragma once
// Draws the engine needs beyond RandomStream's own: a standard normal, a choice by weights.
#include <cmath>
#include <cstddef>
#include <numbers>
#include <span>

#include "pbrfit/core/random_stream.hpp"

namespace pbrfit::gp::detail {

// Box-Muller, one value per call (two uniforms).
inline double normal(RandomStream& random) {
  const double u = 1.0 - random.uniform();  // (0, 1]
  const double v = random.uniform();
  return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * std::numbers::pi * v);
}

// Index k with probability weights[k] / sum; the weights are >= 0 with a positive sum.
inline std::size_t choose_weighted(std::span<const double> weights, RandomStream& random) {
  double total = 0.0;
  for (double w : weights) total += w;
  double point = random.uniform() * total;
  for (std::size_t k = 0; k < weights.size(); ++k) {
    if (point < weights[k]) return k;
    point -= weights[k];
  }
  for (std::size_t k = weights.size(); k-- > 0;) {
    if (weights[k] > 0.0) return k;
  }
  return 0;
}

}  // namespace pbrfit::gp::detail
