#include "pbrfit/gp/variation.hpp"

#include <algorithm>
#include <cmath>

namespace pbrfit::gp {

bool parsimony_better(const Fitness& a, const Fitness& b, double tie_tolerance) {
  const double x = a.evaluated ? a.error : worst_error;
  const double y = b.evaluated ? b.error : worst_error;
  const bool tie = x == y || std::abs(x - y) <= tie_tolerance * std::max(std::abs(x), std::abs(y));
  if (!tie) return x < y;
  return a.cost < b.cost;
}

std::size_t tournament(std::span<const Fitness> fitnesses, std::size_t size, double tie_tolerance,
                       RandomStream& random) {
  std::size_t winner = random.below(fitnesses.size());
  for (std::size_t round = 1; round < size; ++round) {
    const std::size_t contestant = random.below(fitnesses.size());
    if (parsimony_better(fitnesses[contestant], fitnesses[winner], tie_tolerance)) winner = contestant;
  }
  return winner;
}

}  // namespace pbrfit::gp
