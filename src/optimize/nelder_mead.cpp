#include "pbrfit/optimize/nelder_mead.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "simplex_search.hpp"

namespace pbrfit::optimize {
namespace {

class NelderMeadRun {
 public:
  NelderMeadRun(Evaluator& evaluator, const Bounds& bounds, const NelderMeadOptions& options)
      : evaluator_(evaluator), bounds_(bounds), options_(options), search_(evaluator, bounds, options),
        first_evaluation_(evaluator.used()) {}

  NelderMeadResult run(std::span<const double> start, std::optional<double> start_value);

 private:
  StopReason iterate_until_stop();
  bool restart();
  NelderMeadResult result(StopReason reason) const;

  Evaluator& evaluator_;
  const Bounds& bounds_;
  const NelderMeadOptions& options_;
  detail::SimplexSearch search_;
  std::size_t first_evaluation_;
  std::size_t iterations_ = 0;
  std::size_t restarts_ = 0;
  double value_at_last_restart_ = 0.0;
};

NelderMeadResult NelderMeadRun::run(std::span<const double> start, std::optional<double> start_value) {
  std::vector<double> steps = options_.relative_steps;
  if (steps.empty()) steps.assign(bounds_.dimension(), options_.initial_step);
  if (!search_.build(start, steps, start_value)) return result(StopReason::budget);
  return result(iterate_until_stop());
}

StopReason NelderMeadRun::iterate_until_stop() {
  for (;;) {
    if (search_.best().value <= options_.target) return StopReason::target;
    if (iterations_ >= options_.max_iterations) return StopReason::iteration_limit;
    // Values measured at a looser tolerance no longer compare with new ones.
    const bool tightened = evaluator_.follow_scale(search_.simplex().relative_size(bounds_));
    if (tightened && !search_.remeasure()) return StopReason::budget;
    if (search_.collapsed()) {
      if (!restart()) return evaluator_.exhausted() ? StopReason::budget : StopReason::converged;
      continue;  // the fresh simplex goes through the same checks (with no free dimension it is collapsed)
    }
    if (!search_.step()) return StopReason::budget;
    ++iterations_;
  }
}

// A fresh simplex around the best vertex, unless restarts are used up or the previous one did not pay.
bool NelderMeadRun::restart() {
  const detail::Simplex& simplex = search_.simplex();
  const double best = simplex.values[simplex.best()];
  const double gain_needed = std::max(options_.restart_gain_absolute, options_.restart_gain_relative * std::abs(best));
  const bool paid_off = restarts_ == 0 || value_at_last_restart_ - best > gain_needed;
  if (restarts_ >= options_.max_restarts || !paid_off) return false;
  value_at_last_restart_ = best;
  ++restarts_;
  const auto anchor = simplex.row(simplex.best());
  const std::vector<double> center(anchor.begin(), anchor.end());
  const std::vector<double> steps(bounds_.dimension(), options_.restart_step);
  return search_.build(center, steps, best);
}

NelderMeadResult NelderMeadRun::result(StopReason reason) const {
  NelderMeadResult result;
  result.best = search_.best();
  result.evaluations = evaluator_.used() - first_evaluation_;
  result.iterations = iterations_;
  result.restarts = restarts_;
  result.starts_run = result.evaluations > 0 ? 1 : 0;
  result.stop = reason;
  return result;
}

}  // namespace

NelderMeadResult nelder_mead(Evaluator& evaluator, const Bounds& bounds, std::span<const double> start,
                             const NelderMeadOptions& options, std::optional<double> start_value) {
  validate(bounds);
  if (!options.relative_steps.empty() && options.relative_steps.size() != bounds.dimension()) {
    throw std::invalid_argument("optimize: relative_steps must have one step per dimension");
  }
  return NelderMeadRun(evaluator, bounds, options).run(start, start_value);
}

NelderMeadResult nelder_mead(const Objective& objective, const Bounds& bounds, std::span<const double> start,
                             const NelderMeadOptions& options, std::size_t max_evaluations,
                             ToleranceSchedule schedule) {
  Evaluator evaluator(objective, max_evaluations, schedule);
  NelderMeadResult result = nelder_mead(evaluator, bounds, start, options);
  evaluator.finalize(result.best);
  result.evaluations = evaluator.used();
  return result;
}

}  // namespace pbrfit::optimize
