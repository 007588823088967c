#include "fit_run.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "free_dimensions.hpp"
#include "pbrfit/optimize/differential_evolution.hpp"
#include "pbrfit/optimize/nelder_mead.hpp"
#include "polish_steps.hpp"

namespace pbrfit::optimize::detail {

FitRun::FitRun(const Objective& objective, const Bounds& bounds, const FitOptions& options, RandomStream& random)
    : evaluator_(objective, options.max_evaluations, options.tolerance),
      bounds_(bounds),
      options_(options),
      random_(random),
      global_(options.global),
      polish_(options.polish) {
  global_.target = options.target;
  polish_.target = options.target;
}

FitResult FitRun::run(std::span<const std::vector<double>> warm_starts) {
  if (!warm_starts.empty() && options_.polish_warm_starts) polish_warm_starts(warm_starts);
  result_.stop = rounds(warm_starts);
  evaluator_.finalize(best_);
  result_.x = best_.x;
  result_.value = best_.value;
  result_.evaluations = evaluator_.used();
  return result_;
}

std::size_t FitRun::polish_budget() const {
  const double share = std::clamp(options_.polish_share, 0.0, 1.0);
  return static_cast<std::size_t>(share * static_cast<double>(evaluator_.remaining()));
}

void FitRun::polish_warm_starts(std::span<const std::vector<double>> warm_starts) {
  evaluator_.limit_to(evaluator_.used() + polish_budget());
  const NelderMeadResult polished = multi_start_nelder_mead(evaluator_, bounds_, warm_starts, polish_);
  evaluator_.lift_limit();
  if (!polished.best.x.empty() && keep_if_better(polished.best, FitPhase::warm_start)) {
    result_.start = polished.winning_start;
  }
  result_.polish_restarts += polished.restarts;
}

StopReason FitRun::rounds(std::span<const std::vector<double>> warm_starts) {
  std::size_t stalled = 0;
  for (;;) {
    if (best_.value <= options_.target) return StopReason::target;
    if (evaluator_.exhausted()) return StopReason::budget;
    if (result_.rounds >= options_.max_rounds) return StopReason::iteration_limit;
    const bool nothing_to_search = free_dimensions(bounds_).empty();  // one evaluation said everything
    if (result_.rounds > 0 && (stalled >= options_.stall_rounds || nothing_to_search)) return StopReason::converged;
    std::vector<std::vector<double>> seeds;
    if (!best_.x.empty() && (result_.rounds == 0 || options_.seed_rounds_with_best)) seeds.push_back(best_.x);
    if (result_.rounds == 0) seeds.insert(seeds.end(), warm_starts.begin(), warm_starts.end());
    stalled = round(seeds) ? 0 : stalled + 1;
    ++result_.rounds;
  }
}

// One DE search and its polish; true when it improved the best.
bool FitRun::round(std::span<const std::vector<double>> seeds) {
  const std::size_t global_budget = evaluator_.remaining() - polish_budget();
  evaluator_.limit_to(evaluator_.used() + global_budget);
  global_.population_size = population_for(global_budget);
  const DeResult global = differential_evolution(evaluator_, bounds_, global_, random_, seeds);
  evaluator_.lift_limit();
  if (global.best.x.empty()) return false;
  if (global.stop == StopReason::target || evaluator_.exhausted()) return keep_if_better(global.best, FitPhase::global);
  evaluator_.use_final_tolerance();
  polish_.relative_steps = polish_steps(global.population, bounds_, options_.polish);
  const bool known = global.best.tolerance == evaluator_.tolerance();
  const auto start_value = known ? std::optional<double>(global.best.value) : std::nullopt;
  const NelderMeadResult polished = nelder_mead(evaluator_, bounds_, global.best.x, polish_, start_value);
  polish_.relative_steps.clear();
  result_.polish_restarts += polished.restarts;
  if (polished.best.x.empty()) return keep_if_better(global.best, FitPhase::global);
  return keep_if_better(polished.best, polished.best.x == global.best.x ? FitPhase::global : FitPhase::polish);
}

bool FitRun::keep_if_better(const Candidate& candidate, FitPhase phase) {
  const double gain_needed = std::max(options_.polish.restart_gain_absolute,
                                      options_.polish.restart_gain_relative * std::abs(candidate.value));
  const bool first = best_.x.empty();
  if (!first && !(candidate.value < best_.value)) return false;
  const bool improved = first || best_.value - candidate.value > gain_needed;
  best_ = candidate;
  result_.phase = phase;
  result_.round = result_.rounds;
  return improved;
}

// An automatic population is capped so that the round's DE budget covers min_generations generations.
std::size_t FitRun::population_for(std::size_t global_budget) const {
  if (options_.global.population_size > 0) return options_.global.population_size;
  const std::size_t automatic = population_size_for(options_.global, free_dimensions(bounds_).size());
  const std::size_t affordable = global_budget / std::max<std::size_t>(options_.min_generations, 1);
  return std::max<std::size_t>(std::min(automatic, affordable), 1);  // DE raises it to its minimum
}

}  // namespace pbrfit::optimize::detail
