#pragma once
// The knee of a two-objective front: the member farthest from the straight line through the front's two
// extremes, on the side of the ideal point, with cost and log10(error) (errors below 1e-30 count as
// 1e-30) each scaled to [0, 1] over the front. It is where buying accuracy with cost stops paying.
// With fewer than three members, or when no member lies below the line, it is the most accurate member.
#include <cstddef>
#include <span>

#include "pbrfit/gp/fitness.hpp"
#include "pbrfit/gp/pareto_archive.hpp"

namespace pbrfit::gp {

// The index of the knee in `front` (mutually non-dominated fitnesses, any order); front is not empty.
std::size_t knee_index(std::span<const Fitness> front);
std::size_t knee_index(std::span<const ArchiveEntry> front);

}  // namespace pbrfit::gp
