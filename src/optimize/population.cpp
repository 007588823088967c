#include "population.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

#include "random_draws.hpp"
#include "value_order.hpp"

namespace pbrfit::optimize::detail {

Population::Population(std::size_t size, std::size_t dimension)
    : size(size),
      dimension(dimension),
      points(size * dimension, 0.0),
      values(size, std::numeric_limits<double>::infinity()),
      tolerances(size, 0.0),
      weights(size, 0.0),
      crossovers(size, 0.0) {}

std::size_t Population::best_index() const {
  return static_cast<std::size_t>(std::min_element(values.begin(), values.end()) - values.begin());
}

std::vector<std::size_t> Population::ranking() const {
  std::vector<std::size_t> order;
  rank_into(order);
  return order;
}

void Population::rank_into(std::vector<std::size_t>& order) const { order_by_value(values, order); }

void fill_latin_hypercube(Population& population, const Bounds& bounds, RandomStream& random) {
  std::vector<std::size_t> strata(population.size);
  const double stratum_fraction = 1.0 / static_cast<double>(population.size);
  for (std::size_t d = 0; d < population.dimension; ++d) {
    std::iota(strata.begin(), strata.end(), std::size_t{0});
    for (std::size_t i = population.size; i > 1; --i) std::swap(strata[i - 1], strata[index_below(random, i)]);
    for (std::size_t i = 0; i < population.size; ++i) {
      const double fraction = (static_cast<double>(strata[i]) + random.uniform()) * stratum_fraction;
      population.row(i)[d] = std::min(bounds.lower[d] + fraction * bounds.width(d), bounds.upper[d]);
    }
  }
}

void place_seeds(Population& population, const Bounds& bounds, std::span<const std::vector<double>> seeds) {
  const std::size_t count = std::min(seeds.size(), population.size);
  for (std::size_t i = 0; i < count; ++i) {
    std::copy_n(seeds[i].begin(), population.dimension, population.row(i).begin());
    clamp_into(bounds, population.row(i));
  }
}

double relative_spread(const Population& population, const Bounds& bounds) {
  double spread = 0.0;
  for (std::size_t d = 0; d < population.dimension; ++d) {
    if (bounds.is_fixed(d)) continue;
    double lowest = population.points[d];
    double highest = lowest;
    for (std::size_t i = 1; i < population.size; ++i) {
      lowest = std::min(lowest, population.row(i)[d]);
      highest = std::max(highest, population.row(i)[d]);
    }
    spread = std::max(spread, (highest - lowest) / bounds.width(d));
  }
  return spread;
}

}  // namespace pbrfit::optimize::detail
