#include "block_merge.hpp"

#include <algorithm>
#include <utility>

namespace pbrfit::store {

namespace {

void append_values(Block& into, Block& from, std::size_t dimension) {
  into.values.insert(into.values.end(), from.values.begin(), from.values.end());
  into.texts.insert(into.texts.end(), std::make_move_iterator(from.texts.begin()), std::make_move_iterator(from.texts.end()));
  into.count[dimension] += from.count[dimension];
}

// b continues a along the last dimension: both are single lines at the same outer position.
bool continues_line(const Block& a, const Block& b) {
  const std::size_t last = a.count.size() - 1;
  for (std::size_t d = 0; d < last; ++d)
    if (a.count[d] != 1 || b.count[d] != 1 || a.offset[d] != b.offset[d]) return false;
  return b.offset[last] == a.offset[last] + a.count[last];
}

// b continues a along the first dimension: both span every other dimension completely.
bool continues_rows(const Block& a, const Block& b, const std::vector<std::uint64_t>& extent) {
  for (std::size_t d = 1; d < a.count.size(); ++d)
    if (a.offset[d] != 0 || b.offset[d] != 0 || a.count[d] != extent[d] || b.count[d] != extent[d]) return false;
  return b.offset[0] == a.offset[0] + a.count[0];
}

// Merges, in place, each block into the one before it where `rows` (else a line) continues it.
void merge_pass(std::vector<Block>& blocks, bool rows, const std::vector<std::uint64_t>& extent) {
  std::size_t kept = 0;
  for (std::size_t i = 1; i < blocks.size(); ++i) {
    Block& last = blocks[kept];
    if (rows ? continues_rows(last, blocks[i], extent) : continues_line(last, blocks[i]))
      append_values(last, blocks[i], rows ? 0 : last.count.size() - 1);
    else if (++kept != i)
      blocks[kept] = std::move(blocks[i]);
  }
  blocks.resize(kept + 1);
}

// Each block's offset as its row-major position in the table into order[i].first, so that comparing
// positions compares offsets (every offset beyond the first lies inside its extent, as check_block makes
// sure). False, leaving order unusable, when a position would not fit in 64 bits.
bool linear_positions(const std::vector<Block>& blocks, const std::vector<std::uint64_t>& extent,
                      std::vector<std::pair<std::uint64_t, std::size_t>>& order) {
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    std::uint64_t position = blocks[i].offset[0];
    for (std::size_t d = 1; d < extent.size(); ++d)
      if (__builtin_mul_overflow(position, extent[d], &position) ||
          __builtin_add_overflow(position, blocks[i].offset[d], &position))
        return false;
    order[i].first = position;
  }
  return true;
}

}  // namespace

std::vector<Block> merge_touching_blocks(std::vector<Block> blocks, const std::vector<std::uint64_t>& extent) {
  if (blocks.size() < 2 || blocks.front().count.empty()) return blocks;
  // Stable: of two blocks at one offset, the later stays later and so is written last. The order is found
  // on (position, index) pairs, so each block moves at most once, and not at all when the blocks came in order.
  std::vector<std::pair<std::uint64_t, std::size_t>> order(blocks.size());
  for (std::size_t i = 0; i < blocks.size(); ++i) order[i] = {0, i};
  if (linear_positions(blocks, extent, order)) {
    if (!std::is_sorted(order.begin(), order.end())) std::sort(order.begin(), order.end());
  } else {
    const auto by_offset = [&](const auto& a, const auto& b) { return blocks[a.second].offset < blocks[b.second].offset; };
    std::stable_sort(order.begin(), order.end(), by_offset);
  }
  if (!std::is_sorted(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.second < b.second; })) {
    std::vector<Block> sorted;
    sorted.reserve(blocks.size());
    for (const auto& [position, i] : order) sorted.push_back(std::move(blocks[i]));
    blocks = std::move(sorted);
  }
  merge_pass(blocks, false, extent);
  merge_pass(blocks, true, extent);
  return blocks;
}

}  // namespace pbrfit::store
