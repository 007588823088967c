#include "simplex.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "value_order.hpp"

namespace pbrfit::optimize::detail {

Simplex::Simplex(std::size_t count, std::size_t dimension)
    : count(count),
      dimension(dimension),
      points(count * dimension, 0.0),
      values(count, std::numeric_limits<double>::infinity()),
      order(count) {
  std::iota(order.begin(), order.end(), std::size_t{0});
}

void Simplex::sort() { order_by_value(values, order); }

double Simplex::relative_size(const Bounds& bounds) const {
  const auto anchor = row(best());
  double size = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    const auto vertex = row(i);
    for (std::size_t d = 0; d < dimension; ++d) {
      if (!bounds.is_fixed(d)) size = std::max(size, std::abs(vertex[d] - anchor[d]) / bounds.width(d));
    }
  }
  return size;
}

void Simplex::centroid_without_worst(std::span<double> out) const {
  std::fill(out.begin(), out.end(), 0.0);
  for (std::size_t k = 0; k + 1 < count; ++k) {
    const auto vertex = row(order[k]);
    for (std::size_t d = 0; d < dimension; ++d) out[d] += vertex[d];
  }
  const double share = 1.0 / static_cast<double>(count - 1);
  for (double& coordinate : out) coordinate *= share;
}

}  // namespace pbrfit::optimize::detail
