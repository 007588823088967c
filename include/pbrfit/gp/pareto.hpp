#pragma once
// Pareto fronts of programs: NSGA-II ranking and survivor selection, the archive of every non-dominated
// program a run has seen, and the knee of a two-objective front.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "pbrfit/gp/fitness.hpp"
#include "pbrfit/gp/program.hpp"

namespace pbrfit::gp {

// ---- Ranking ----
// NSGA-II's ranking (Deb et al. 2002; Pesce & Iwanicki 2015, section 5.1): non-dominated fronts and
// crowding distances over the first `objective_count` objectives of a set of fitnesses.
//
// Invariants:
//  - fronts partition the indices; no member of a front dominates another member of the same front, and
//    every member of front f > 0 is dominated by some member of front f - 1; members are in index order;
//  - crowding distances are >= 0 or +inf (the extremes of each objective); an objective whose range over
//    the front is 0 or not finite adds nothing;
//  - everything is a pure function of the values (ties broken by index), so it is reproducible.

std::vector<std::vector<std::size_t>> nondominated_fronts(std::span<const Fitness> fitnesses,
                                                          std::size_t objective_count);

// One distance per member of `front`, in the same order.
std::vector<double> crowding_distances(std::span<const Fitness> fitnesses, std::span<const std::size_t> front,
                                       std::size_t objective_count);

struct ParetoRanking {
  std::vector<std::size_t> rank;  // the front of each fitness
  std::vector<double> crowding;   // its crowding distance within that front

  // NSGA-II's crowded comparison: lower rank, then larger crowding distance.
  bool better(std::size_t a, std::size_t b) const {
    return rank[a] != rank[b] ? rank[a] < rank[b] : crowding[a] > crowding[b];
  }
};

ParetoRanking rank_by_pareto(std::span<const Fitness> fitnesses, std::size_t objective_count);

// NSGA-II's environmental selection of `count` survivors (count <= fitnesses.size()): whole fronts in
// order, the last one cut by crowding distance. A fitness with the same objectives as an earlier one is a
// duplicate and competes only for the places the distinct ones leave (it keeps a population diverse).
// Returns indices, best first.
std::vector<std::size_t> select_survivors(std::span<const Fitness> fitnesses, std::size_t count,
                                          std::size_t objective_count);

// ---- The archive ----
// Every non-dominated program a run has seen (Pesce & Iwanicki 2015, section 5.1), with the generation it
// appeared in, so the trade-off between error and cost can be chosen after the run.
//
// Invariants: no entry dominates another and no two entries have the same objectives (the first one seen
// is kept); every entry is evaluated with a finite error; entries are sorted by cost, then error, then
// piecewise count, so with two objectives the error falls along the list. The result of a sequence of
// insertions depends only on the entries and their order.

struct ArchiveEntry {
  Program program;
  Fitness fitness;
  std::uint64_t generation = 0;  // when the program was first evaluated
};

class ParetoArchive {
 public:
  explicit ParetoArchive(std::size_t objective_count = 2);

  // Adds the entry unless it is unevaluated, has a non-finite error, or an entry dominates it or has the
  // same objectives; removes the entries it dominates. True when it was added.
  bool insert(const ArchiveEntry& entry);
  // Whether insert() would add an entry with this fitness (a cheap test before building the entry).
  bool admits(const Fitness& fitness) const;
  void insert_all(std::span<const ArchiveEntry> entries);

  const std::vector<ArchiveEntry>& entries() const { return entries_; }
  std::size_t size() const { return entries_.size(); }
  std::size_t objective_count() const { return objective_count_; }

 private:
  std::size_t objective_count_;
  std::vector<ArchiveEntry> entries_;
};

// ---- The knee ----
// The knee of a two-objective front: the member farthest from the straight line through the front's two
// extremes, on the side of the ideal point, with cost and log10(error) (errors below 1e-30 count as
// 1e-30) each scaled to [0, 1] over the front. It is where buying accuracy with cost stops paying.
// With fewer than three members, or when no member lies below the line, it is the most accurate member.

// The index of the knee in `front` (mutually non-dominated fitnesses, any order); front is not empty.
std::size_t knee_index(std::span<const Fitness> front);
std::size_t knee_index(std::span<const ArchiveEntry> front);

}  // namespace pbrfit::gp
