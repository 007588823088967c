#pragma once
// The default fitter (Pesce & Iwanicki 2015, section 3.3): a global search by Differential Evolution,
// polished by Nelder-Mead with restarts from the DE best, in rounds: a round after the first restarts DE
// from a fresh population (independent of the earlier rounds unless seed_rounds_with_best), and the
// best point over all rounds is kept. Warm starts (e.g. the fits of neighbouring cells of a sweep) are
// first polished by multi-start Nelder-Mead (unless polish_warm_starts is false), then seeded into the
// first round's population.
//
// Contract:
//  - every objective evaluation of every phase is counted; evaluations <= max_evaluations always;
//  - the warm-start polish may spend at most polish_share of the budget;
//  - DE may spend at most (1 - polish_share) of what remains when its round begins; it also ends when its
//    population has converged or stagnated (options.global), and the polish gets the rest;
//  - the first DE round follows the tolerance schedule; its polish and everything after it run at the
//    final tolerance (the tolerance never loosens), and the reported value is always measured at the
//    final tolerance (re-measured with a held-back evaluation when the budget ended the search earlier);
//  - rounds stop on the budget, on the target, after max_rounds, or after stall_rounds rounds in a row
//    that did not improve the best;
//  - same inputs and the same random stream state give bitwise identical results.
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/optimize/bounds.hpp"
#include "pbrfit/optimize/differential_evolution.hpp"
#include "pbrfit/optimize/nelder_mead.hpp"
#include "pbrfit/optimize/objective.hpp"
#include "pbrfit/optimize/stop_reason.hpp"
#include "pbrfit/optimize/tolerance_schedule.hpp"

namespace pbrfit::optimize {

// The fitter's DE: jDE-style self-adaptive DE/rand/1/bin (F in [0.1, 1], CR starting at 0.9); a round
// ends when the population has narrowed to 3% of the box or its best has stalled for 100 generations.
DeOptions default_global_options();
// The fitter's Nelder-Mead: standard coefficients, with restarts.
NelderMeadOptions default_polish_options();

struct FitOptions {
  std::size_t max_evaluations = 20'000;
  DeOptions global = default_global_options();
  NelderMeadOptions polish = default_polish_options();
  double polish_share = 0.2;  // in [0, 1]
  // With an automatic population size (global.population_size == 0), a round's population is also capped
  // so that its DE budget covers at least this many generations.
  std::size_t min_generations = 200;
  std::size_t max_rounds = 1000;
  std::size_t stall_rounds = 2;
  bool seed_rounds_with_best = false;  // whether a round after the first seeds DE with the best so far
  bool polish_warm_starts = true;      // false: warm starts are only seeded into the first round
  ToleranceSchedule tolerance;
  double target = -std::numeric_limits<double>::infinity();  // stop once the best value <= target
};

enum class FitPhase {
  warm_start,  // the Nelder-Mead polish of the warm starts
  global,      // a DE round
  polish,      // the Nelder-Mead polish of a DE round's best
};

struct FitResult {
  std::vector<double> x;        // the best point found
  double value = std::numeric_limits<double>::infinity();  // its value at tolerance.final
  std::size_t evaluations = 0;  // all phases, the final re-measurement included
  FitPhase phase = FitPhase::global;  // the phase that found x
  std::size_t round = 0;        // the DE round that found x (global or polish phase)
  std::size_t start = 0;        // the warm start whose polish found x (warm_start phase)
  std::size_t rounds = 0;       // rounds begun
  std::size_t polish_restarts = 0;
  StopReason stop = StopReason::budget;
};

// warm_starts (points in the box's dimension) are polished first, then seeded into the first round.
FitResult fit(const Objective& objective, const Bounds& bounds, const FitOptions& options, RandomStream& random,
              std::span<const std::vector<double>> warm_starts = {});

}  // namespace pbrfit::optimize
