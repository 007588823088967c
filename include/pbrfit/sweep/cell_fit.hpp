#pragma once
// Fitting one cell of a sweep, warm-started from the fits of earlier cells (Pesce & Iwanicki 2015,
// section 3.3: a coarse level's fits start the fine one, and the global search runs only where the warm
// start fits poorly).
//  1. Warm starts are polished by multi-start Nelder-Mead (at most warm_evaluations evaluations). The
//     best is kept without a global search when the policy is `never`, or `when_poor` and its error is at
//     most max(poor_ratio * the smallest source error, poor_absolute).
//  2. Otherwise the default fitter (DE -> Nelder-Mead, optimize/fit.hpp) runs with `global`, its first
//     round seeded with the polished point and the warm starts; the better of both phases is kept.
//  Without warm starts: Nelder-Mead from the problem's default start when the policy is `never`, else the
//  default fitter with the default start (if any) as its warm start.
//  3. A problem with a refinement (a second objective made from the fit: an LTC fitted to its lobe, then to
//     the lights it is judged by) is polished from the fit on that objective by Nelder-Mead for
//     refinement_evaluations evaluations; the result is the refined point and its refined objective.
//
// Contract: deterministic for the same inputs and stream state; evaluations counts every objective call
// of both phases; the reported error is the objective at the returned parameters (at the final tolerance).
#include <cstddef>
#include <functional>
#include <limits>
#include <span>
#include <vector>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/optimize/fit.hpp"
#include "pbrfit/optimize/nelder_mead.hpp"
#include "pbrfit/optimize/parameter_space.hpp"

namespace pbrfit::sweep {

enum class GlobalPolicy { always, when_poor, never };

struct CellFitOptions {
  GlobalPolicy policy = GlobalPolicy::when_poor;
  double poor_ratio = 2.0;
  double poor_absolute = 0.0;
  std::size_t warm_evaluations = 400;
  optimize::NelderMeadOptions warm_search{};
  optimize::FitOptions global{};
};

// A fitted cell offered as a start: its parameters (model coordinates) and its error.
struct WarmStart {
  std::vector<double> parameters;
  double error = std::numeric_limits<double>::infinity();
};

// The problem of one cell: the model's parameters, the error to minimize over them, an optional default
// start (model coordinates; empty for none) and an optional canonical form: where a cell fixes some
// parameters and derives them from others (an LTC at normal view has m11 = m00), `canonical` rewrites a
// searched point into the parameters the error actually used, and results are reported in that form.
struct CellProblem {
  optimize::ParameterSpace parameters;
  optimize::Objective error = [](std::span<const double>) { return std::numeric_limits<double>::infinity(); };
  std::vector<double> default_start;
  std::function<void(std::span<double>)> canonical;
  // When set: the second objective, made from the fitted parameters (model coordinates) and their error.
  std::function<optimize::Objective(std::span<const double> fitted, double fitted_error)> refinement;
  std::size_t refinement_evaluations = 0;
};

enum class Winner { global, default_start, warm_start };

struct CellFitResult {
  std::vector<double> parameters;  // model coordinates
  double error = std::numeric_limits<double>::infinity();
  std::size_t evaluations = 0;
  Winner winner = Winner::global;
  std::size_t warm_index = 0;  // which warm start won, when winner == warm_start
  bool global_ran = false;
};

CellFitResult fit_cell(const CellProblem& problem, std::span<const WarmStart> warm_starts,
                       const CellFitOptions& options, RandomStream& random);

}  // namespace pbrfit::sweep
