#include "pbrfit/optimize/fit.hpp"

#include <stdexcept>

#include "fit_run.hpp"

namespace pbrfit::optimize {

DeOptions default_global_options() {
  DeOptions options;
  options.strategy = DeStrategy::rand_1;
  options.control = WeightControl::self_adaptive;
  options.weight = 0.5;
  options.weight_min = 0.1;
  options.weight_max = 1.0;
  options.crossover = 0.9;
  options.min_spread = 3e-2;
  options.stagnation_generations = 100;
  return options;
}

NelderMeadOptions default_polish_options() { return NelderMeadOptions{}; }

FitResult fit(const Objective& objective, const Bounds& bounds, const FitOptions& options, RandomStream& random,
              std::span<const std::vector<double>> warm_starts) {
  validate(bounds);
  for (const auto& start : warm_starts) {
    if (start.size() != bounds.dimension()) throw std::invalid_argument("optimize: a warm start has the wrong size");
  }
  return detail::FitRun(objective, bounds, options, random).run(warm_starts);
}

}  // namespace pbrfit::optimize
