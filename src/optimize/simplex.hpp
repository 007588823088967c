#pragma once
// The working simplex of a Nelder-Mead run: `count` vertices of `dimension` coordinates stored row by
// row, their values, and the vertex order by value.
//
// Invariants: points.size() == count * dimension; values and order have `count` entries; after sort(),
// order lists the vertices by increasing value, ties in vertex order.
#include <cstddef>
#include <span>
#include <vector>

#include "pbrfit/optimize/bounds.hpp"

namespace pbrfit::optimize::detail {

struct Simplex {
  Simplex(std::size_t count, std::size_t dimension);

  std::span<double> row(std::size_t i) { return {points.data() + i * dimension, dimension}; }
  std::span<const double> row(std::size_t i) const { return {points.data() + i * dimension, dimension}; }
  std::size_t best() const { return order.front(); }
  std::size_t worst() const { return order.back(); }
  std::size_t second_worst() const { return order[order.size() - 2]; }

  void sort();
  // Largest |vertex - best vertex| / box width over the vertices and the free dimensions.
  double relative_size(const Bounds& bounds) const;
  double value_spread() const { return values[worst()] - values[best()]; }
  // The mean of every vertex but the worst, into `out`.
  void centroid_without_worst(std::span<double> out) const;

  std::size_t count;
  std::size_t dimension;
  std::vector<double> points;
  std::vector<double> values;
  std::vector<std::size_t> order;
};

}  // namespace pbrfit::optimize::detail
