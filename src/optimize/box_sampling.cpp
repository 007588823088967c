#include "pbrfit/optimize/box_sampling.hpp"

#include "population.hpp"

namespace pbrfit::optimize {

std::vector<std::vector<double>> latin_hypercube(const Bounds& bounds, std::size_t count, RandomStream& random) {
  validate(bounds);
  if (count == 0) return {};
  detail::Population sample(count, bounds.dimension());
  detail::fill_latin_hypercube(sample, bounds, random);
  std::vector<std::vector<double>> points;
  for (std::size_t i = 0; i < count; ++i) points.emplace_back(sample.row(i).begin(), sample.row(i).end());
  return points;
}

}  // namespace pbrfit::optimize
