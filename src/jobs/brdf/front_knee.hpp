#pragma once
// The knee of a genBRDF front: gp::knee_index over the members more accurate than the front's best
// input-free member (a tree reading none of n·l, n·v, ...: a fitted constant colour, which ignores light
// and view). It and the members worse than it sit at the cheap end of every front; left in, the jump
// from them to the first real BRDF makes the knee a constant. When no member beats it, or none is
// input-free, the whole front counts. Private to the brdf jobs.
#include <cstddef>
#include <span>

#include "pbrfit/jobs/brdf/tree_bytes.hpp"

namespace pbrfit::jobs::brdf {

// The index of the knee in `front` (not empty; mutually non-dominated in error and size).
std::size_t front_knee(std::span<const ScoredTree> front);

}  // namespace pbrfit::jobs::brdf
