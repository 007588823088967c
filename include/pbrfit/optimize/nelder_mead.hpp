#pragma once
// Nelder-Mead with restarts, and its multi-start form (Pesce & Iwanicki 2015, section 3.2.2); options in
// nelder_mead_options.hpp.
//
// Contract:
//  - every point it evaluates lies in the box: reflected, expanded and contracted points are clamped;
//  - the best candidate is the best value evaluated at the run's tightest tolerance: when the evaluator's
//    tolerance tightens (it follows the simplex's relative size) the simplex is re-evaluated first;
//  - a run stops on the budget, the iteration limit, the target, or a collapse that restarts cannot fix;
//  - the result depends only on the inputs (no randomness).
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "pbrfit/optimize/bounds.hpp"
#include "pbrfit/optimize/candidate.hpp"
#include "pbrfit/optimize/evaluator.hpp"
#include "pbrfit/optimize/nelder_mead_options.hpp"
#include "pbrfit/optimize/stop_reason.hpp"

namespace pbrfit::optimize {

struct NelderMeadResult {
  Candidate best;
  std::size_t evaluations = 0;  // spent by this run (all starts)
  std::size_t iterations = 0;
  std::size_t restarts = 0;     // fresh simplices built after a collapse
  std::size_t winning_start = 0;  // multi-start: index of the start whose run found `best`
  std::size_t starts_run = 1;     // multi-start: starts that got at least one evaluation
  StopReason stop = StopReason::budget;
};

// On a shared evaluator; re-measuring the best at the final tolerance is left to the caller.
// `start_value`, when given, is the start point's value at the evaluator's current tolerance and saves
// its evaluation (the start must then lie in the box).
NelderMeadResult nelder_mead(Evaluator& evaluator, const Bounds& bounds, std::span<const double> start,
                             const NelderMeadOptions& options, std::optional<double> start_value = {});

// One run per start point, in order, while the budget lasts; the best run wins (earliest on ties).
NelderMeadResult multi_start_nelder_mead(Evaluator& evaluator, const Bounds& bounds,
                                         std::span<const std::vector<double>> starts,
                                         const NelderMeadOptions& options);

// Standalone: its own evaluator with `max_evaluations` and `schedule`; best is at the final tolerance.
NelderMeadResult nelder_mead(const Objective& objective, const Bounds& bounds, std::span<const double> start,
                             const NelderMeadOptions& options, std::size_t max_evaluations,
                             ToleranceSchedule schedule = {});

}  // namespace pbrfit::optimize
