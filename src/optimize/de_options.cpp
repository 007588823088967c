#include "pbrfit/optimize/de_options.hpp"

#include <algorithm>

namespace pbrfit::optimize {

std::size_t population_size_for(const DeOptions& options, std::size_t free_dimensions) {
  constexpr std::size_t smallest = 5;  // the target and four distinct donors
  const std::size_t automatic = std::min<std::size_t>(40, 10 * free_dimensions);
  return std::max(smallest, options.population_size > 0 ? options.population_size : automatic);
}

}  // namespace pbrfit::optimize
