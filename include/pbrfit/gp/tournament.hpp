#pragma once
// Tournament selection with parsimony pressure (the alternative to Pareto selection): `size` contestants
// drawn uniformly with replacement; the lowest error wins, and errors within `tie_tolerance` (relative)
// of each other tie, which the lower cost breaks (lexicographic parsimony), then the earlier draw.
#include <cstddef>
#include <span>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/gp/fitness.hpp"

namespace pbrfit::gp {

// a is better than b: lower error beyond the tolerance, else lower cost.
bool parsimony_better(const Fitness& a, const Fitness& b, double tie_tolerance);

std::size_t tournament(std::span<const Fitness> fitnesses, std::size_t size, double tie_tolerance,
                       RandomStream& random);

}  // namespace pbrfit::gp
