#pragma once
// NSGA-II's ranking (Deb et al. 2002; Pesce & Iwanicki 2015, section 5.1): non-dominated fronts and
// crowding distances over the first `objective_count` objectives of a set of fitnesses.
//
// Invariants:
//  - fronts partition the indices; no member of a front dominates another member of the same front, and
//    every member of front f > 0 is dominated by some member of front f - 1; members are in index order;
//  - crowding distances are >= 0 or +inf (the extremes of each objective); an objective whose range over
//    the front is 0 or not finite adds nothing;
//  - everything is a pure function of the values (ties broken by index), so it is reproducible.
#include <cstddef>
#include <span>
#include <vector>

#include "pbrfit/gp/fitness.hpp"

namespace pbrfit::gp {

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

}  // namespace pbrfit::gp
