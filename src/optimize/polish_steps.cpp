#include "polish_steps.hpp"

#include <algorithm>

namespace pbrfit::optimize::detail {

std::vector<double> polish_steps(const std::vector<Candidate>& population, const Bounds& bounds,
                                 const NelderMeadOptions& polish) {
  std::vector<double> steps(bounds.dimension(), polish.initial_step);
  const double smallest = std::min(10.0 * polish.x_tolerance, polish.initial_step);
  for (std::size_t d = 0; d < bounds.dimension(); ++d) {
    if (bounds.is_fixed(d) || population.empty()) continue;
    double lowest = population.front().x[d];
    double highest = lowest;
    for (const Candidate& member : population) {
      lowest = std::min(lowest, member.x[d]);
      highest = std::max(highest, member.x[d]);
    }
    steps[d] = std::clamp((highest - lowest) / bounds.width(d), smallest, polish.initial_step);
  }
  return steps;
}

}  // namespace pbrfit::optimize::detail
