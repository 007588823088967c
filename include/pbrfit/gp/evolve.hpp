#pragma once
// One island's evolution for a number of generations, as a pure function (the epoch of the island model,
// Brady et al., section 3.2): the island's population and the migrants from its ring neighbour come in,
// the evolved population, the archive additions and statistics go out. The ring itself (who sends to
// whom, every how many generations) is the caller's.
//
// Contract:
//  - members and migrants without a fitness are evaluated first (counted); migrants then join the
//    population, which is cut back to population_size by the selection scheme;
//  - generation g (counted across calls by Population::generation) draws its random numbers from
//    random.derive(g), offspring slot i from random.derive(g).derive(i): the result depends only on the
//    inputs and the stream's key, bitwise, never on threads or timing;
//  - an island whose best error has stalled for restart_after_stall generations restarts from random
//    programs drawn from random.derive(g).derive(2^32 + i) before generation g breeds;
//  - it stops after `generations` generations, after the generation that reached target_error, or when
//    max_evaluations would be exceeded (offspring not evaluated by then are dropped);
//  - archive_additions holds the non-dominated programs among everything evaluated in this call;
//  - programs with non-finite outputs get the worst error and never enter the archive.
#include <cstddef>
#include <span>
#include <vector>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/gp/dataset.hpp"
#include "pbrfit/gp/evolve_options.hpp"
#include "pbrfit/gp/pareto_archive.hpp"
#include "pbrfit/gp/pareto_ranking.hpp"
#include "pbrfit/gp/population.hpp"

namespace pbrfit::gp {

struct EvolveStats {
  std::size_t generations = 0;  // completed in this call
  std::size_t evaluations = 0;  // program evaluations in this call, constant fitting included
  std::size_t constant_fit_evaluations = 0;
  std::size_t restarts = 0;
  double best_error = worst_error;  // over the final population
  bool reached_target = false;
  bool budget_exhausted = false;
};

struct EvolveResult {
  Population population;
  std::vector<ArchiveEntry> archive_additions;
  EvolveStats stats;
};

EvolveResult evolve(const Population& island, std::span<const Individual> migrants, std::size_t generations,
                    const EvolveOptions& options, const Dataset& dataset, const RandomStream& random);

// options.population_size random programs (not evaluated yet), slot i drawn from random.derive(i).
Population random_population(const EvolveOptions& options, const RandomStream& random);

// The `count` best members to send to the next island: by Pareto rank, then error, then cost (pareto
// scheme: the most accurate members of the front first) or by error with parsimony (tournament scheme);
// ties go to the earlier member.
std::vector<Individual> pick_emigrants(const Population& population, std::size_t count, const EvolveOptions& options);

}  // namespace pbrfit::gp
