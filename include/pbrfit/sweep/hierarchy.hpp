#pragma once
// The levels of a hierarchical sweep (Pesce & Iwanicki 2015, section 3.3: coarse fits warm-start fine
// ones). Level 0 is the coarsest; the last level is the requested grid. Going one level coarser halves
// every axis that can be halved: edges keep both ends, (n - 1) / 2 intervals rounded up (at least 1),
// centres ceil(n / 2) cells; an axis of one sample stays one sample.
//
// Invariants: level_count >= 1 and every level differs from the next (hierarchy() throws
// std::invalid_argument, with the largest possible count, when the grid cannot be halved that often);
// nearest_parent() maps every fine cell to the coarse cell whose axis values are nearest on every axis
// (ties to the lower index).
#include <cstddef>
#include <vector>

#include "pbrfit/sweep/level_grid.hpp"

namespace pbrfit::sweep {

// How many levels a grid allows: halving until no axis shrinks any more.
std::size_t max_level_count(const std::vector<GridAxis>& finest);

std::vector<LevelGrid> hierarchy(const std::vector<GridAxis>& finest, std::size_t level_count);

// The cell of `coarse` nearest to `cell` of `fine` (both of the same axes and ranges).
std::size_t nearest_parent(const LevelGrid& fine, std::size_t cell, const LevelGrid& coarse);

}  // namespace pbrfit::sweep
