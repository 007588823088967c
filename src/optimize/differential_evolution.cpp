#include "pbrfit/optimize/differential_evolution.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <stdexcept>

#include "free_dimensions.hpp"
#include "population.hpp"
#include "random_draws.hpp"

namespace pbrfit::optimize {
namespace {

using namespace detail;  // Population, the random draws and the free dimensions, shared with other searches

// Trial control: where each trial's mutation weight F and crossover probability CR come from
// (WeightControl). How many random numbers a draw consumes depends on the control mode and the stream
// only, never on objective values.
struct TrialControl {
  double weight;     // F
  double crossover;  // CR
};

class TrialControlSource {
 public:
  explicit TrialControlSource(const DeOptions& options) : options_(options) {}

  // Gives every member the starting F and CR of the self-adaptive variant.
  void initialize(Population& population) const;
  void start_generation(RandomStream& random);
  TrialControl draw(const Population& population, std::size_t target, RandomStream& random) const;

 private:
  const DeOptions& options_;
  double generation_weight_ = 0.0;
};

constexpr double redraw_probability = 0.1;  // jDE's tau_1 = tau_2

void TrialControlSource::initialize(Population& population) const {
  std::fill(population.weights.begin(), population.weights.end(), options_.weight);
  std::fill(population.crossovers.begin(), population.crossovers.end(), options_.crossover);
}

void TrialControlSource::start_generation(RandomStream& random) {
  if (options_.control == WeightControl::dither_per_generation) {
    generation_weight_ = uniform_in(random, options_.weight_min, options_.weight_max);
  }
}

TrialControl TrialControlSource::draw(const Population& population, std::size_t target, RandomStream& random) const {
  switch (options_.control) {
    case WeightControl::fixed:
      return {options_.weight, options_.crossover};
    case WeightControl::dither_per_generation:
      return {generation_weight_, options_.crossover};
    case WeightControl::dither_per_vector:
      return {uniform_in(random, options_.weight_min, options_.weight_max), options_.crossover};
    case WeightControl::self_adaptive: {
      TrialControl control{population.weights[target], population.crossovers[target]};
      if (random.uniform() < redraw_probability) {
        control.weight = uniform_in(random, options_.weight_min, options_.weight_max);
      }
      if (random.uniform() < redraw_probability) control.crossover = random.uniform();
      return control;
    }
  }
  return {options_.weight, options_.crossover};
}

// One trial vector: mutation by the configured strategy, binomial crossover with the target, then the
// bound handling. The trial lies in the box; fixed dimensions keep the target's value; the forced
// crossover dimension j_rand is drawn among the free dimensions; the population holds at least 5 members.
struct TrialContext {
  const Population& population;
  const Bounds& bounds;
  const DeOptions& options;
  std::span<const std::size_t> free_dimensions;  // not empty
  std::span<const std::size_t> ranking;          // members by increasing value (best first)
};


// A member index different from every index in `taken`.
std::size_t draw_other(RandomStream& random, std::size_t size, std::initializer_list<std::size_t> taken) {
  for (;;) {
    const std::size_t index = index_below(random, size);
    if (std::find(taken.begin(), taken.end(), index) == taken.end()) return index;
  }
}

// The mutant is base + F (plus - minus) + F (toward - target), the last term for current_to_pbest only.
struct Donors {
  std::size_t base;
  std::size_t plus;
  std::size_t minus;
  std::size_t toward;
};

Donors pick_donors(const TrialContext& context, std::size_t target, RandomStream& random) {
  const std::size_t size = context.population.size;
  if (context.options.strategy == DeStrategy::current_to_pbest) {
    const auto top = static_cast<double>(size) * context.options.pbest_fraction;
    const std::size_t pool = std::clamp<std::size_t>(static_cast<std::size_t>(std::ceil(top)), 2, size);
    const std::size_t toward = context.ranking[index_below(random, pool)];
    const std::size_t plus = draw_other(random, size, {target});
    return {target, plus, draw_other(random, size, {target, plus}), toward};
  }
  const std::size_t first = draw_other(random, size, {target});
  const std::size_t second = draw_other(random, size, {target, first});
  if (context.options.strategy == DeStrategy::best_1) return {context.ranking[0], first, second, target};
  return {first, second, draw_other(random, size, {target, first, second}), target};
}

double repair(const Bounds& bounds, std::size_t d, double value, BoundHandling handling, RandomStream& random) {
  if (value >= bounds.lower[d] && value <= bounds.upper[d]) return value;
  if (handling == BoundHandling::reinitialize) return uniform_in(random, bounds.lower[d], bounds.upper[d]);
  return std::clamp(value, bounds.lower[d], bounds.upper[d]);
}


void build_trial(const TrialContext& context, std::size_t target, TrialControl control, RandomStream& random,
                 std::span<double> trial) {
  const Population& population = context.population;
  const Donors donors = pick_donors(context, target, random);
  const auto current = population.row(target);
  const auto base = population.row(donors.base);
  const auto plus = population.row(donors.plus);
  const auto minus = population.row(donors.minus);
  const auto toward = population.row(donors.toward);
  std::copy(current.begin(), current.end(), trial.begin());
  const std::size_t forced = context.free_dimensions[index_below(random, context.free_dimensions.size())];
  for (std::size_t d : context.free_dimensions) {
    if (d != forced && !(random.uniform() < control.crossover)) continue;
    const double mutant =
        base[d] + control.weight * (plus[d] - minus[d]) + control.weight * (toward[d] - current[d]);
    trial[d] = repair(context.bounds, d, mutant, context.options.bound_handling, random);
  }
}

// Counts consecutive generations in which the best value did not improve by more than
// max(absolute, relative |reference|), where the reference is the best value at the last improvement.
class StagnationMonitor {
 public:
  StagnationMonitor(double relative, double absolute) : relative_(relative), absolute_(absolute) {}

  void observe(double best);
  std::size_t stale_generations() const { return stale_; }

 private:
  double relative_;
  double absolute_;
  double reference_ = std::numeric_limits<double>::infinity();
  std::size_t stale_ = 0;
};

void StagnationMonitor::observe(double best) {
  const bool first_finite = !std::isfinite(reference_) && std::isfinite(best);
  const double threshold = std::max(absolute_, relative_ * std::abs(reference_));
  if (first_finite || reference_ - best > threshold) {
    reference_ = best;
    stale_ = 0;
  } else {
    ++stale_;
  }
}

// One run: the population, the trials of the current generation and the stopping state.
// population_ and trials_ have the same size; every evaluation goes through evaluator_; generations_
// counts completed generations only.
class DeRun {
 public:
  DeRun(Evaluator& evaluator, const Bounds& bounds, const DeOptions& options, RandomStream& random);

  DeResult run(std::span<const std::vector<double>> seeds);

 private:
  void initialize(std::span<const std::vector<double>> seeds);
  bool stop_before_generation(StopReason& reason);
  bool stagnated() const;
  void generation();
  void evaluate_member(Population& members, std::size_t i);
  DeResult result(StopReason reason) const;

  Evaluator& evaluator_;
  const Bounds& bounds_;
  const DeOptions& options_;
  RandomStream& random_;
  std::vector<std::size_t> free_;
  std::size_t size_;
  Population population_;
  Population trials_;
  std::vector<std::size_t> ranking_;  // of population_, refreshed every generation
  TrialControlSource controls_;
  StagnationMonitor stagnation_;
  std::size_t first_evaluation_;
  std::size_t generations_ = 0;
};

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

void check_seeds(const Bounds& bounds, std::span<const std::vector<double>> seeds) {
  for (const auto& seed : seeds) {
    if (seed.size() != bounds.dimension()) throw std::invalid_argument("optimize: a seed point has the wrong size");
  }
}

}  // namespace

std::size_t population_size_for(const DeOptions& options, std::size_t free_dimensions) {
  constexpr std::size_t smallest = 5;  // the target and four distinct donors
  const std::size_t automatic = std::min<std::size_t>(40, 10 * free_dimensions);
  return std::max(smallest, options.population_size > 0 ? options.population_size : automatic);
}

DeResult differential_evolution(Evaluator& evaluator, const Bounds& bounds, const DeOptions& options,
                                RandomStream& random, std::span<const std::vector<double>> seeds) {
  validate(bounds);
  check_seeds(bounds, seeds);
  return DeRun(evaluator, bounds, options, random).run(seeds);
}

DeResult differential_evolution(const Objective& objective, const Bounds& bounds, const DeOptions& options,
                                std::size_t max_evaluations, RandomStream& random,
                                std::span<const std::vector<double>> seeds, ToleranceSchedule schedule) {
  Evaluator evaluator(objective, max_evaluations, schedule);
  DeResult result = differential_evolution(evaluator, bounds, options, random, seeds);
  evaluator.finalize(result.best);
  result.evaluations = evaluator.used();
  return result;
}

}  // namespace pbrfit::optimize
