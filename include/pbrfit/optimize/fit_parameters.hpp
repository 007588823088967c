#pragma once
// The default fitter (fit.hpp) over a ParameterSpace: it searches the internal box while the objective,
// the warm starts and the result's x are the model's parameters.
//
// Contract: as fit(); result.x == space.from_internal(internal best), and result.value was measured at
// exactly that point.
#include <span>
#include <vector>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/optimize/fit.hpp"
#include "pbrfit/optimize/parameter_space.hpp"

namespace pbrfit::optimize {

FitResult fit(const Objective& model_objective, const ParameterSpace& space, const FitOptions& options,
              RandomStream& random, std::span<const std::vector<double>> warm_starts = {});

}  // namespace pbrfit::optimize
