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
//
// Its settings, EvolveOptions: the defaults are a sensible start for symbolic regression on a few inputs:
// bench_gp_nguyen runs them (only the operators, precision and target set) and reports its recovery
// rates; frequent restarts of stalled islands paid off most there.
//
// Invariants (validate() checks them): population_size >= 2; tournament_size >= 1; elites <
// population_size; rates and shares in [0, 1]; at least one mutation weight > 0; the shape is valid.
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/gp/constant_fitting.hpp"
#include "pbrfit/gp/dataset.hpp"
#include "pbrfit/gp/fitness_evaluator.hpp"
#include "pbrfit/gp/pareto.hpp"
#include "pbrfit/gp/population.hpp"
#include "pbrfit/gp/program_shape.hpp"
#include "pbrfit/gp/variation.hpp"

namespace pbrfit::gp {

enum class SelectionScheme {
  pareto,      // NSGA-II: parents by crowded tournament, survivors by fronts and crowding (error, cost[, piecewise])
  tournament,  // parents by tournament with parsimony pressure; the next generation is elites + offspring
};

struct EvolveOptions {
  ProgramShape shape;
  MutationOptions mutation;
  FitnessOptions fitness;
  ConstantFitOptions constants;

  std::size_t population_size = 500;
  SelectionScheme selection = SelectionScheme::pareto;
  bool piecewise_objective = false;  // a third objective: the number of piecewise operators
  std::size_t tournament_size = 2;   // parents: crowded (pareto) or parsimony (tournament) tournaments
  double tie_tolerance = 1e-12;      // relative error difference the parsimony tournament calls a tie
  std::size_t elites = 1;            // tournament scheme: the best members kept unchanged

  double crossover_rate = 0.9;            // the chance an offspring starts from two parents
  double subgraph_crossover_share = 0.5;  // of crossovers: subgraph crossover; the rest string crossover
  double mutation_rate = 0.5;             // the chance a crossover child is also mutated (a copy always is)

  // After each generation the offspring with the lowest errors among those with live constants get their
  // constants fitted (constant_fitting.hpp), at most this many.
  std::size_t constant_fits_per_generation = 1;

  // Restart: once the island's best error has not improved (by more than a relative 1e-9) for this many
  // generations, its population is replaced by random programs (0: never). What it found stays in the
  // archive; independent restarts turn a large budget into many fresh attempts.
  std::size_t restart_after_stall = 10;

  std::size_t max_evaluations = std::numeric_limits<std::size_t>::max();  // per evolve() call
  double target_error = 0.0;  // stop after the generation whose best error is <= this

  std::size_t objective_count() const { return piecewise_objective ? 3 : 2; }
};

// Throws std::invalid_argument when an invariant does not hold.
void validate(const EvolveOptions& options);

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
