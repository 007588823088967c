#include "pbrfit/gp/knee.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace pbrfit::gp {
namespace {

double log_error(const Fitness& f) { return std::log10(std::max(f.error, 1e-30)); }

std::size_t most_accurate(std::span<const Fitness> front) {
  std::size_t best = 0;
  for (std::size_t m = 1; m < front.size(); ++m) {
    if (front[m].error < front[best].error ||
        (front[m].error == front[best].error && front[m].cost < front[best].cost)) {
      best = m;
    }
  }
  return best;
}

}  // namespace

std::size_t knee_index(std::span<const Fitness> front) {
  const std::size_t accurate = most_accurate(front);
  if (front.size() < 3) return accurate;
  std::size_t cheap = 0;
  for (std::size_t m = 1; m < front.size(); ++m) {
    if (front[m].cost < front[cheap].cost ||
        (front[m].cost == front[cheap].cost && front[m].error < front[cheap].error)) {
      cheap = m;
    }
  }
  // Scaled coordinates: x = cost, y = log error; the extremes are (0, 1) (cheap) and (1, 0) (accurate).
  const double cost_range = front[accurate].cost - front[cheap].cost;
  const double error_range = log_error(front[cheap]) - log_error(front[accurate]);
  if (!(cost_range > 0.0) || !(error_range > 0.0)) return accurate;
  std::size_t knee = accurate;
  double farthest = 0.0;
  for (std::size_t m = 0; m < front.size(); ++m) {
    const double x = (front[m].cost - front[cheap].cost) / cost_range;
    const double y = (log_error(front[m]) - log_error(front[accurate])) / error_range;
    const double below_line = 1.0 - x - y;  // proportional to the distance to the line x + y = 1
    if (below_line > farthest) {
      farthest = below_line;
      knee = m;
    }
  }
  return knee;
}

std::size_t knee_index(std::span<const ArchiveEntry> front) {
  std::vector<Fitness> fitnesses;
  fitnesses.reserve(front.size());
  for (const ArchiveEntry& entry : front) fitnesses.push_back(entry.fitness);
  return knee_index(fitnesses);
}

}  // namespace pbrfit::gp
