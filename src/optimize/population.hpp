#pragma once
// A DE population: `size` points of `dimension` coordinates stored row by row, their values with the
// tolerance each was measured at, and the per-member F and CR of the self-adaptive variant.
//
// Invariants: points.size() == size * dimension; the other vectors have `size` entries; an unevaluated
// member has value +inf.
#include <cstddef>
#include <span>
#include <vector>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/optimize/bounds.hpp"

namespace pbrfit::optimize::detail {

struct Population {
  Population(std::size_t size, std::size_t dimension);

  std::span<double> row(std::size_t i) { return {points.data() + i * dimension, dimension}; }
  std::span<const double> row(std::size_t i) const { return {points.data() + i * dimension, dimension}; }
  // The lowest value; the earliest member on ties.
  std::size_t best_index() const;
  // Member indices by increasing value; ties keep member order.
  std::vector<std::size_t> ranking() const;
  void rank_into(std::vector<std::size_t>& order) const;

  std::size_t size;
  std::size_t dimension;
  std::vector<double> points;
  std::vector<double> values;
  std::vector<double> tolerances;
  std::vector<double> weights;
  std::vector<double> crossovers;
};

// A Latin hypercube sample of the box: in every dimension each of the `size` equal strata holds one point.
void fill_latin_hypercube(Population& population, const Bounds& bounds, RandomStream& random);

// Overwrites the first members with the seed points, clamped into the box (extra seeds are ignored).
void place_seeds(Population& population, const Bounds& bounds, std::span<const std::vector<double>> seeds);

// Largest over the free dimensions of (max - min of the members' coordinates) / box width; 0 when every
// dimension is fixed.
double relative_spread(const Population& population, const Bounds& bounds);

}  // namespace pbrfit::optimize::detail
