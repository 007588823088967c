#pragma once
// Fixed, weighted node sets for deterministic quasi-Monte Carlo estimates of integrals,
// sum_i weights[i] f(node i) ~ integral of f (Pesce & Iwanicki 2015, section 7.3):
//  - box_qmc_nodes: the first `count` Halton points (radical inverses in the first primes) scaled into the
//    box, each weighing volume / count;
//  - direction_qmc_nodes: unit directions over the sphere, or the upper hemisphere (z >= 0), from two
//    strategies of `count` Halton points each, uniform and cosine-weighted about +z, combined by the
//    balance heuristic: a node drawn by either weighs 1 / (count (p_uniform + p_cosine)) at it.
//
// Invariants: pure functions of their arguments; points are row-major (node i's coordinates at
// i * dimension); weights are > 0 and sum to the domain's measure up to the estimate's error (exactly for
// the box). The box has 1 to 16 dimensions with lower < upper in each (std::invalid_argument otherwise).
#include <cstddef>
#include <span>
#include <vector>

namespace pbrfit::integrate {

struct WeightedNodes {
  std::size_t dimension = 0;
  std::vector<double> points;
  std::vector<double> weights;

  std::size_t size() const { return weights.size(); }
  std::span<const double> node(std::size_t i) const { return {points.data() + i * dimension, dimension}; }
};

WeightedNodes box_qmc_nodes(std::span<const double> lower, std::span<const double> upper, std::size_t count);

WeightedNodes direction_qmc_nodes(std::size_t count, bool hemisphere);

}  // namespace pbrfit::integrate
