#pragma once
// Start points spread over a box, for multi-start searches: a Latin hypercube sample (in every free
// dimension each of `count` equal strata holds exactly one point, placed uniformly within it).
// Fixed dimensions take their single value. Deterministic in the stream's state.
#include <cstddef>
#include <vector>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/optimize/bounds.hpp"

namespace pbrfit::optimize {

std::vector<std::vector<double>> latin_hypercube(const Bounds& bounds, std::size_t count, RandomStream& random);

}  // namespace pbrfit::optimize
