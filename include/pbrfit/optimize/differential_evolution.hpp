#pragma once
// Differential Evolution over a box (Pesce & Iwanicki 2015, section 3.2.1); options in de_options.hpp.
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
#include <cstddef>
#include <span>
#include <vector>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/optimize/bounds.hpp"
#include "pbrfit/optimize/candidate.hpp"
#include "pbrfit/optimize/de_options.hpp"
#include "pbrfit/optimize/evaluator.hpp"
#include "pbrfit/optimize/stop_reason.hpp"

namespace pbrfit::optimize {

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
