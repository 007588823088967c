#include "pbrfit/sweep/cell_fit.hpp"

#include <algorithm>
#include <cmath>

#include "pbrfit/optimize/evaluator.hpp"
#include "pbrfit/optimize/nelder_mead.hpp"

namespace pbrfit::sweep {
namespace {

// The best point of a phase, in the internal box.
struct PhaseBest {
  optimize::Candidate best;
  std::size_t evaluations = 0;
  std::size_t start = 0;  // index of the winning start of a multi-start polish
};

PhaseBest polish(const optimize::Objective& internal, const optimize::Bounds& box,
                 const std::vector<std::vector<double>>& starts, const CellFitOptions& options) {
  const auto schedule = optimize::ToleranceSchedule::constant(options.global.tolerance.final);
  optimize::Evaluator evaluator(internal, std::max<std::size_t>(options.warm_evaluations, 1), schedule);
  const auto result = optimize::multi_start_nelder_mead(evaluator, box, starts, options.warm_search);
  return {result.best, evaluator.used(), result.winning_start};
}

double acceptance_threshold(std::span<const WarmStart> warm_starts, const CellFitOptions& options) {
  double smallest = std::numeric_limits<double>::infinity();
  for (const auto& start : warm_starts)
    if (std::isfinite(start.error)) smallest = std::min(smallest, start.error);
  const double relative = std::isfinite(smallest) ? options.poor_ratio * smallest : -1.0;
  return std::max(relative, options.poor_absolute);
}

CellFitResult result_from(const CellProblem& problem, const optimize::Candidate& best, std::size_t evaluations,
                          Winner winner, std::size_t warm_index, bool global_ran) {
  CellFitResult out;
  out.parameters = problem.parameters.from_internal(best.x);
  if (problem.canonical) problem.canonical(out.parameters);
  out.error = best.value;
  out.evaluations = evaluations;
  out.winner = winner;
  out.warm_index = warm_index;
  out.global_ran = global_ran;
  return out;
}

// Step 3 of the header: the fit polished on the refinement objective.
CellFitResult refined(const CellProblem& problem, CellFitResult fit, const CellFitOptions& options) {
  const optimize::Objective objective = problem.refinement(fit.parameters, fit.error);
  const optimize::Objective internal = problem.parameters.internal_objective(objective);
  CellFitOptions polishing = options;
  polishing.warm_evaluations = problem.refinement_evaluations;
  const PhaseBest best = polish(internal, problem.parameters.internal_bounds(),
                                {problem.parameters.to_internal(fit.parameters)}, polishing);
  fit.parameters = problem.parameters.from_internal(best.best.x);
  if (problem.canonical) problem.canonical(fit.parameters);
  fit.error = best.best.value;
  fit.evaluations += best.evaluations;
  return fit;
}

// Steps 1 and 2 of the header.
CellFitResult first_fit(const CellProblem& problem, std::span<const WarmStart> warm_starts,
                        const CellFitOptions& options, RandomStream& random) {
  const optimize::Objective internal = problem.parameters.internal_objective(problem.error);
  const optimize::Bounds box = problem.parameters.internal_bounds();
  std::vector<std::vector<double>> starts;
  for (const auto& start : warm_starts) starts.push_back(problem.parameters.to_internal(start.parameters));
  const bool from_default = starts.empty() && !problem.default_start.empty();
  if (from_default) starts.push_back(problem.parameters.to_internal(problem.default_start));
  const Winner start_kind = from_default ? Winner::default_start : Winner::warm_start;

  PhaseBest warm;
  const bool polish_first = !warm_starts.empty() || (from_default && options.policy == GlobalPolicy::never);
  if (polish_first) {
    warm = polish(internal, box, starts, options);
    const bool accept = options.policy == GlobalPolicy::never ||
                        (options.policy == GlobalPolicy::when_poor &&
                         warm.best.value <= acceptance_threshold(warm_starts, options));
    if (accept) return result_from(problem, warm.best, warm.evaluations, start_kind, warm.start, false);
    starts.insert(starts.begin(), warm.best.x);
  }
  optimize::FitOptions global = options.global;
  global.polish_warm_starts = !polish_first;
  const auto fitted = optimize::fit(internal, box, global, random, starts);
  const std::size_t evaluations = warm.evaluations + fitted.evaluations;
  if (polish_first && !(fitted.value < warm.best.value))
    return result_from(problem, warm.best, evaluations, start_kind, warm.start, true);
  optimize::Candidate best{fitted.x, fitted.value, global.tolerance.final};
  const bool start_won = fitted.phase == optimize::FitPhase::warm_start;
  return result_from(problem, best, evaluations, start_won ? start_kind : Winner::global, fitted.start, true);
}

}  // namespace

CellFitResult fit_cell(const CellProblem& problem, std::span<const WarmStart> warm_starts,
                       const CellFitOptions& options, RandomStream& random) {
  CellFitResult fit = first_fit(problem, warm_starts, options, random);
  if (problem.refinement && problem.refinement_evaluations > 0) return refined(problem, std::move(fit), options);
  return fit;
}

}  // namespace pbrfit::sweep
