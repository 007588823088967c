#pragma once
// The starting simplex of the fitter's polish matches the region DE narrowed down to: per dimension, the
// extent of DE's final population relative to the box width, kept within
// [10 x_tolerance, initial_step] of the polish options (fixed dimensions get initial_step; unused).
#include <vector>

#include "pbrfit/optimize/bounds.hpp"
#include "pbrfit/optimize/candidate.hpp"
#include "pbrfit/optimize/nelder_mead.hpp"

namespace pbrfit::optimize::detail {

std::vector<double> polish_steps(const std::vector<Candidate>& population, const Bounds& bounds,
                                 const NelderMeadOptions& polish);

}  // namespace pbrfit::optimize::detail
