#include "pbrfit/optimize/fit_parameters.hpp"

#include <stdexcept>

namespace pbrfit::optimize {

FitResult fit(const Objective& model_objective, const ParameterSpace& space, const FitOptions& options,
              RandomStream& random, std::span<const std::vector<double>> warm_starts) {
  if (space.size() == 0) throw std::invalid_argument("optimize: the parameter space is empty");
  std::vector<std::vector<double>> internal_starts;
  for (const auto& start : warm_starts) {
    if (start.size() != space.size()) throw std::invalid_argument("optimize: a warm start has the wrong size");
    internal_starts.push_back(space.to_internal(start));
  }
  FitResult result = fit(space.internal_objective(model_objective), space.internal_bounds(), options, random,
                         internal_starts);
  if (!result.x.empty()) result.x = space.from_internal(result.x);
  return result;
}

}  // namespace pbrfit::optimize
