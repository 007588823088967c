#include "trial_control.hpp"

#include <algorithm>

#include "random_draws.hpp"

namespace pbrfit::optimize::detail {
namespace {

constexpr double redraw_probability = 0.1;  // jDE's tau_1 = tau_2

}  // namespace

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

}  // namespace pbrfit::optimize::detail
