#include "pbrfit/gp/pareto.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace pbrfit::gp {

// ---- Ranking ----

namespace {

// The objectives of every fitness as plain numbers (an unevaluated fitness counts as the worst; objectives
// beyond the count are 0).
struct Points {
  Points(std::span<const Fitness> fitnesses, std::size_t objective_count) : count(objective_count) {
    values.reserve(fitnesses.size());
    for (const Fitness& f : fitnesses) {
      values.push_back({f.evaluated ? f.error : worst_error, objective_count > 1 ? f.cost : 0.0, objective_count > 2 ? f.piecewise : 0.0});
    }
  }
  bool dominates(std::size_t a, std::size_t b) const {
    bool better = false;
    for (std::size_t k = 0; k < count; ++k) {
      if (values[a][k] > values[b][k]) return false;
      better = better || values[a][k] < values[b][k];
    }
    return better;
  }
  bool lexicographically_before(std::size_t a, std::size_t b) const {
    for (std::size_t k = 0; k < count; ++k) {
      if (values[a][k] != values[b][k]) return values[a][k] < values[b][k];
    }
    return a < b;
  }
  std::size_t count;
  std::vector<std::array<double, 3>> values;
};

std::vector<std::size_t> lexicographic_order(const Points& points, std::span<const std::size_t> ids) {
  std::vector<std::size_t> order(ids.begin(), ids.end());
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return points.lexicographically_before(a, b); });
  return order;
}

// Efficient non-dominated sort (Zhang et al. 2015): in lexicographic order no later point dominates an
// earlier one, so each point joins the first front none of whose members dominates it. Being dominated
// by front f implies being dominated by every earlier front, so the fronts are binary searched; with two
// objectives a front's last member is the only one to check. `ordered` is in lexicographic order.
std::vector<std::vector<std::size_t>> sort_fronts(const Points& points, std::span<const std::size_t> ordered) {
  std::vector<std::vector<std::size_t>> fronts;
  for (std::size_t p : ordered) {
    auto dominated_by = [&](const std::vector<std::size_t>& front) {
      if (points.count <= 2) return points.dominates(front.back(), p);
      return std::any_of(front.rbegin(), front.rend(), [&](std::size_t q) { return points.dominates(q, p); });
    };
    auto front = std::partition_point(fronts.begin(), fronts.end(), dominated_by);
    if (front == fronts.end()) front = fronts.insert(fronts.end(), std::vector<std::size_t>{});
    front->push_back(p);
  }
  for (auto& front : fronts) std::sort(front.begin(), front.end());
  return fronts;
}

}  // namespace

std::vector<std::vector<std::size_t>> nondominated_fronts(std::span<const Fitness> fitnesses,
                                                          std::size_t objective_count) {
  const Points points(fitnesses, objective_count);
  std::vector<std::size_t> ids(fitnesses.size());
  std::iota(ids.begin(), ids.end(), std::size_t{0});
  return sort_fronts(points, lexicographic_order(points, ids));
}

std::vector<double> crowding_distances(std::span<const Fitness> fitnesses, std::span<const std::size_t> front,
                                       std::size_t objective_count) {
  constexpr double infinity = std::numeric_limits<double>::infinity();
  std::vector<double> distance(front.size(), 0.0);
  std::vector<std::size_t> order(front.size());
  for (std::size_t k = 0; k < objective_count; ++k) {
    std::iota(order.begin(), order.end(), std::size_t{0});
    auto value = [&](std::size_t m) { return fitnesses[front[m]].objective(k); };
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return value(a) < value(b); });
    const double range = value(order.back()) - value(order.front());
    distance[order.front()] = distance[order.back()] = infinity;
    if (!(range > 0.0) || !std::isfinite(range)) continue;
    for (std::size_t m = 1; m + 1 < order.size(); ++m) {
      distance[order[m]] += (value(order[m + 1]) - value(order[m - 1])) / range;
    }
  }
  return distance;
}

ParetoRanking rank_by_pareto(std::span<const Fitness> fitnesses, std::size_t objective_count) {
  ParetoRanking ranking{std::vector<std::size_t>(fitnesses.size()), std::vector<double>(fitnesses.size())};
  const auto fronts = nondominated_fronts(fitnesses, objective_count);
  for (std::size_t f = 0; f < fronts.size(); ++f) {
    const auto distances = crowding_distances(fitnesses, fronts[f], objective_count);
    for (std::size_t m = 0; m < fronts[f].size(); ++m) {
      ranking.rank[fronts[f][m]] = f;
      ranking.crowding[fronts[f][m]] = distances[m];
    }
  }
  return ranking;
}

namespace {

// Appends up to `count` - chosen.size() of `ids`: whole fronts, the last cut by crowding distance.
// `ordered` is in lexicographic order.
void fill_from_fronts(std::span<const Fitness> fitnesses, const Points& points, std::span<const std::size_t> ordered,
                      std::size_t count, std::vector<std::size_t>& chosen) {
  const std::size_t objective_count = points.count;
  for (const auto& front : sort_fronts(points, ordered)) {
    if (chosen.size() >= count) return;
    if (chosen.size() + front.size() <= count) {
      chosen.insert(chosen.end(), front.begin(), front.end());
      continue;
    }
    const auto distances = crowding_distances(fitnesses, front, objective_count);
    std::vector<std::size_t> order(front.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return distances[a] > distances[b]; });
    for (std::size_t m = 0; chosen.size() < count; ++m) chosen.push_back(front[order[m]]);
  }
}

}  // namespace

std::vector<std::size_t> select_survivors(std::span<const Fitness> fitnesses, std::size_t count,
                                          std::size_t objective_count) {
  std::vector<std::size_t> all(fitnesses.size());
  std::iota(all.begin(), all.end(), std::size_t{0});
  std::vector<std::size_t> distinct;
  std::vector<std::size_t> duplicates;
  const Points points(fitnesses, objective_count);
  const auto order = lexicographic_order(points, all);
  for (std::size_t m = 0; m < order.size(); ++m) {
    const bool repeat = m > 0 && points.values[order[m]] == points.values[order[m - 1]];
    (repeat ? duplicates : distinct).push_back(order[m]);
  }
  std::vector<std::size_t> chosen;
  fill_from_fronts(fitnesses, points, distinct, count, chosen);
  fill_from_fronts(fitnesses, points, duplicates, count, chosen);
  return chosen;
}

// ---- The archive ----

namespace {

bool listed_before(const Fitness& a, const Fitness& b) {
  if (a.cost != b.cost) return a.cost < b.cost;
  if (a.error != b.error) return a.error < b.error;
  return a.piecewise < b.piecewise;
}

}  // namespace

ParetoArchive::ParetoArchive(std::size_t objective_count) : objective_count_(objective_count) {
  if (objective_count < 1 || objective_count > 3) throw std::invalid_argument("an archive has 1 to 3 objectives");
}

bool ParetoArchive::admits(const Fitness& candidate) const {
  if (!candidate.evaluated || !std::isfinite(candidate.error)) return false;
  return std::none_of(entries_.begin(), entries_.end(), [&](const ArchiveEntry& kept) {
    return dominates(kept.fitness, candidate, objective_count_) ||
           same_objectives(kept.fitness, candidate, objective_count_);
  });
}

bool ParetoArchive::insert(const ArchiveEntry& entry) {
  const Fitness& candidate = entry.fitness;
  if (!admits(candidate)) return false;
  std::erase_if(entries_,
                [&](const ArchiveEntry& kept) { return dominates(candidate, kept.fitness, objective_count_); });
  const auto place = std::upper_bound(entries_.begin(), entries_.end(), entry,
                                      [](const auto& a, const auto& b) { return listed_before(a.fitness, b.fitness); });
  entries_.insert(place, entry);
  return true;
}

void ParetoArchive::insert_all(std::span<const ArchiveEntry> entries) {
  for (const ArchiveEntry& entry : entries) insert(entry);
}

// ---- The knee ----

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
