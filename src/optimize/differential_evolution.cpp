#include "pbrfit/optimize/differential_evolution.hpp"

#include <stdexcept>

#include "de_run.hpp"

namespace pbrfit::optimize {
namespace {

void check_seeds(const Bounds& bounds, std::span<const std::vector<double>> seeds) {
  for (const auto& seed : seeds) {
    if (seed.size() != bounds.dimension()) throw std::invalid_argument("optimize: a seed point has the wrong size");
  }
}

}  // namespace

DeResult differential_evolution(Evaluator& evaluator, const Bounds& bounds, const DeOptions& options,
                                RandomStream& random, std::span<const std::vector<double>> seeds) {
  validate(bounds);
  check_seeds(bounds, seeds);
  return detail::DeRun(evaluator, bounds, options, random).run(seeds);
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
