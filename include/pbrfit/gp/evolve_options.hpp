#pragma once
// The settings of an island's evolution (evolve.hpp). The defaults are a sensible start for symbolic
// regression on a few inputs: bench_gp_nguyen runs them (only the operators, precision and target set)
// and reports its recovery rates; frequent restarts of stalled islands paid off most there.
//
// Invariants (validate() checks them): population_size >= 2; tournament_size >= 1; elites <
// population_size; rates and shares in [0, 1]; at least one mutation weight > 0; the shape is valid.
#include <cstddef>
#include <limits>

#include "pbrfit/gp/constant_fitting.hpp"
#include "pbrfit/gp/fitness_evaluator.hpp"
#include "pbrfit/gp/mutation.hpp"
#include "pbrfit/gp/program_shape.hpp"

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

}  // namespace pbrfit::gp
