#pragma once
// Differential Evolution over a box (Pesce & Iwanicki 2015, section 3.2.1): its options and the run, the
// whole of it in this header and differential_evolution.cpp (the population it shares with box sampling).
//
// Contract:
//  - the initial population is a Latin hypercube sample of the box (one point per stratum and dimension),
//    with its first members replaced by the given seed points (clamped into the box; seeds beyond the
//    population size are ignored) for warm starts;
//  - generations are synchronous: all trials of a generation are built from the previous one, then each
//    trial replaces its target when its value is not worse;
//  - before every generation the evaluator's tolerance follows the population's relative spread
//    (tolerance_schedule.hpp); values measured at coarser tolerances are kept, as noisy estimates;
//  - a generation cut short by the budget still runs selection on the trials that were evaluated;
//  - the result depends only on the inputs and the random stream's state (bitwise reproducible).
//
// Options (DeOptions). Defaults follow the course: DE/rand/1/bin, F = 0.5, CR = 0.5, a population of
// min(40, 10 D).
//
// Mutation (x_best: the best of the previous generation; r1, r2, r3 distinct and different from i):
//   rand_1:           v = x_r1 + F (x_r2 - x_r3)
//   best_1:           v = x_best + F (x_r1 - x_r2)
//   current_to_pbest: v = x_i + F (x_p - x_i) + F (x_r1 - x_r2), x_p drawn from the best
//                     max(2, pbest_fraction N) vectors (a blend of DE/best and DE/rand)
// Binomial crossover takes v_j with probability CR and always for one dimension j_rand per vector.
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/optimize/bounds.hpp"
#include "pbrfit/optimize/candidate.hpp"
#include "pbrfit/optimize/evaluator.hpp"
#include "pbrfit/optimize/stop_reason.hpp"

namespace pbrfit::optimize {

enum class DeStrategy { rand_1, best_1, current_to_pbest };

enum class WeightControl {
  fixed,                  // F = weight, CR = crossover
  dither_per_generation,  // F uniform in [weight_min, weight_max], drawn once per generation
  dither_per_vector,      // F uniform in [weight_min, weight_max], drawn for every trial vector
  self_adaptive,          // jDE: every vector carries its own F and CR; a trial redraws them with
                          // probability 0.1 each (F in [weight_min, weight_max], CR in [0, 1]) and
                          // keeps them when it wins; they start at weight and crossover
};

enum class BoundHandling {
  clamp,         // a coordinate outside the box moves to the nearest bound
  reinitialize,  // a coordinate outside the box is redrawn uniformly within its bounds
};

struct DeOptions {
  DeStrategy strategy = DeStrategy::rand_1;
  std::size_t population_size = 0;  // 0: min(40, 10 D) over the free dimensions D; never below 5
  WeightControl control = WeightControl::fixed;
  double weight = 0.5;              // F
  double weight_min = 0.5;          // dither / self-adaptive range of F
  double weight_max = 1.0;
  double crossover = 0.5;           // CR
  double pbest_fraction = 0.1;      // current_to_pbest only
  BoundHandling bound_handling = BoundHandling::clamp;

  // Stopping; a run also stops when its evaluator is exhausted.
  std::size_t max_generations = std::numeric_limits<std::size_t>::max();
  std::size_t stagnation_generations = 0;  // 0: off. Stop after this many generations without improvement
  double stagnation_relative = 1e-6;       // improvement means best drops by more than
  double stagnation_absolute = 1e-12;      //   max(stagnation_absolute, stagnation_relative |best|)
  double min_spread = 0.0;                 // stop when the relative population spread falls below this
  double target = -std::numeric_limits<double>::infinity();  // stop once best <= target
};

// The population size DeOptions resolves to for `free_dimensions` dimensions that are not fixed.
std::size_t population_size_for(const DeOptions& options, std::size_t free_dimensions);


struct DeResult {
  Candidate best;
  std::vector<Candidate> population;  // the final population, best first (ties keep population order)
  std::size_t evaluations = 0;        // spent by this run
  std::size_t generations = 0;        // completed generations, the initial population not counted
  StopReason stop = StopReason::budget;
};

// Runs on a shared evaluator and leaves re-measuring the best at the final tolerance to the caller
// (Evaluator::finalize).
DeResult differential_evolution(Evaluator& evaluator, const Bounds& bounds, const DeOptions& options,
                                RandomStream& random, std::span<const std::vector<double>> seeds = {});

// Standalone: its own evaluator with `max_evaluations` and `schedule`; best is at the final tolerance.
DeResult differential_evolution(const Objective& objective, const Bounds& bounds, const DeOptions& options,
                                std::size_t max_evaluations, RandomStream& random,
                                std::span<const std::vector<double>> seeds = {}, ToleranceSchedule schedule = {});

}  // namespace pbrfit::optimize
