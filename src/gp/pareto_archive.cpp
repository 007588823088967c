#include "pbrfit/gp/pareto_archive.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pbrfit::gp {
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

}  // namespace pbrfit::gp
