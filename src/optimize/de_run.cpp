#include "de_run.hpp"

#include <algorithm>

#include "free_dimensions.hpp"
#include "trial_vector.hpp"

namespace pbrfit::optimize::detail {

DeRun::DeRun(Evaluator& evaluator, const Bounds& bounds, const DeOptions& options, RandomStream& random)
    : evaluator_(evaluator),
      bounds_(bounds),
      options_(options),
      random_(random),
      free_(free_dimensions(bounds)),
      size_(population_size_for(options, free_.size())),
      population_(size_, bounds.dimension()),
      trials_(size_, bounds.dimension()),
      controls_(options),
      stagnation_(options.stagnation_relative, options.stagnation_absolute),
      first_evaluation_(evaluator.used()) {}

DeResult DeRun::run(std::span<const std::vector<double>> seeds) {
  initialize(seeds);
  StopReason reason = StopReason::budget;
  while (!stop_before_generation(reason)) generation();
  return result(reason);
}

void DeRun::initialize(std::span<const std::vector<double>> seeds) {
  fill_latin_hypercube(population_, bounds_, random_);
  place_seeds(population_, bounds_, seeds);
  controls_.initialize(population_);
  const std::size_t distinct = free_.empty() ? 1 : size_;  // with nothing to move, one point says it all
  for (std::size_t i = 0; i < distinct && !evaluator_.exhausted(); ++i) evaluate_member(population_, i);
  stagnation_.observe(population_.values[population_.best_index()]);
}

void DeRun::evaluate_member(Population& members, std::size_t i) {
  members.values[i] = evaluator_.measure(members.row(i));
  members.tolerances[i] = evaluator_.tolerance();
}

bool DeRun::stop_before_generation(StopReason& reason) {
  const double spread = relative_spread(population_, bounds_);
  if (population_.values[population_.best_index()] <= options_.target) {
    reason = StopReason::target;
  } else if (evaluator_.exhausted()) {
    reason = StopReason::budget;
  } else if (generations_ >= options_.max_generations) {
    reason = StopReason::iteration_limit;
  } else if (stagnated()) {
    reason = StopReason::stagnation;
  } else if (spread < options_.min_spread || free_.empty()) {
    reason = StopReason::spread;
  } else {
    evaluator_.follow_scale(spread);
    return false;
  }
  return true;
}

bool DeRun::stagnated() const {
  return options_.stagnation_generations > 0 && stagnation_.stale_generations() >= options_.stagnation_generations;
}

void DeRun::generation() {
  controls_.start_generation(random_);
  population_.rank_into(ranking_);
  const TrialContext context{population_, bounds_, options_, free_, ranking_};
  std::size_t evaluated = 0;
  for (; evaluated < size_ && !evaluator_.exhausted(); ++evaluated) {
    const TrialControl control = controls_.draw(population_, evaluated, random_);
    build_trial(context, evaluated, control, random_, trials_.row(evaluated));
    trials_.weights[evaluated] = control.weight;
    trials_.crossovers[evaluated] = control.crossover;
    evaluate_member(trials_, evaluated);
  }
  for (std::size_t i = 0; i < evaluated; ++i) {
    if (!(trials_.values[i] <= population_.values[i])) continue;
    std::copy_n(trials_.row(i).begin(), bounds_.dimension(), population_.row(i).begin());
    population_.values[i] = trials_.values[i];
    population_.tolerances[i] = trials_.tolerances[i];
    population_.weights[i] = trials_.weights[i];
    population_.crossovers[i] = trials_.crossovers[i];
  }
  if (evaluated == size_) ++generations_;
  stagnation_.observe(population_.values[population_.best_index()]);
}

DeResult DeRun::result(StopReason reason) const {
  DeResult result;
  for (std::size_t i : population_.ranking()) {
    const auto row = population_.row(i);
    result.population.push_back({{row.begin(), row.end()}, population_.values[i], population_.tolerances[i]});
  }
  result.best = result.population.front();
  result.evaluations = evaluator_.used() - first_evaluation_;
  result.generations = generations_;
  result.stop = reason;
  return result;
}

}  // namespace pbrfit::optimize::detail
