#pragma once
// Merging the blocks of one table that touch, so that a flush writes a few large hyperslabs instead of
// many small ones (a table filled cell by cell becomes one write per run of cells). Merging never changes
// which value lands where. Private to the store.
#include <cstdint>
#include <vector>

#include "pbrfit/store/result_layout.hpp"

namespace pbrfit::store {

// `blocks` all belong to one table whose dimensions beyond the first have the given extents (extent[0] is
// ignored), each already passed by check_block. Returns them sorted by offset, touching neighbours merged; a
// later block for the same cells still overwrites an earlier one.
std::vector<Block> merge_touching_blocks(std::vector<Block> blocks, const std::vector<std::uint64_t>& extent);

}  // namespace pbrfit::store
