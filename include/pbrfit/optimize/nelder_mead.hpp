#pragma once
// Nelder-Mead with restarts, and its multi-start form (Pesce & Iwanicki 2015, section 3.2.2): its options,
// its starting simplex and the run, the whole of it in this header and nelder_mead.cpp.
//
// Contract:
//  - every point it evaluates lies in the box: reflected, expanded and contracted points are clamped;
//  - the best candidate is the best value evaluated at the run's tightest tolerance: when the evaluator's
//    tolerance tightens (it follows the simplex's relative size) the simplex is re-evaluated first;
//  - a run stops on the budget, the iteration limit, the target, or a collapse that restarts cannot fix;
//  - the result depends only on the inputs (no randomness).
//
// Options (NelderMeadOptions). The coefficients default to the standard ones: reflection 1, expansion 2,
// contraction 0.5 (the inside contraction x_o - 0.5 (x_o - x_worst) is the course's sigma = -0.5; the
// outside one is x_o + 0.5 (x_r - x_o)), shrink 0.5.
//
// Convergence: the simplex has collapsed when its relative size (largest |vertex - best vertex| / box
// width over vertices and free dimensions) is <= x_tolerance and the spread of its values is
// <= max(f_tolerance_absolute, f_tolerance_relative |best|). A collapse triggers a restart, a fresh
// simplex around the best vertex with restart_step, while restarts remain and the previous restart
// improved the best by more than max(restart_gain_absolute, restart_gain_relative |best|).
#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "pbrfit/optimize/bounds.hpp"
#include "pbrfit/optimize/candidate.hpp"
#include "pbrfit/optimize/evaluator.hpp"
#include "pbrfit/optimize/stop_reason.hpp"

namespace pbrfit::optimize {

struct NelderMeadOptions {
  double reflection = 1.0;
  double expansion = 2.0;
  double contraction = 0.5;
  double shrink = 0.5;

  double initial_step = 0.1;          // offset of each starting vertex, relative to the box width
  std::vector<double> relative_steps;  // per dimension; overrides initial_step when not empty
  double restart_step = 0.1;          // offset of each vertex of a restart simplex, relative to the width

  double x_tolerance = 1e-9;
  double f_tolerance_absolute = 1e-14;
  double f_tolerance_relative = 1e-10;
  std::size_t max_restarts = 20;
  double restart_gain_absolute = 1e-14;
  double restart_gain_relative = 1e-10;

  std::size_t max_iterations = std::numeric_limits<std::size_t>::max();  // over all restarts
  double target = -std::numeric_limits<double>::infinity();              // stop once best <= target
};

// The simplex Nelder-Mead starts (and restarts) from: the start point clamped into the box, plus one
// vertex per free dimension d, offset from it along axis d only by relative_steps[d] times the width.
//
// Invariants: every vertex lies in the box; the offsets are non-zero, so the simplex is never degenerate
// in the free dimensions (its edge vectors are a scaled identity). An offset that would leave the box
// goes the other way; when neither side has room for it, it spans the larger side entirely. Steps below
// 1e-12 count as 1e-12, and an offset too small to change the coordinate spans the larger side. Fixed
// dimensions get no vertex: the simplex has (free dimensions + 1) vertices.
// relative_steps holds one positive step per dimension of the box.
std::vector<std::vector<double>> starting_simplex(const Bounds& bounds, std::span<const double> start,
                                                  std::span<const double> relative_steps);

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
