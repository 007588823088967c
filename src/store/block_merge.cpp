#include "block_merge.hpp"

#include <algorithm>

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

std::vector<Block> merge_pass(std::vector<Block> blocks, bool rows, const std::vector<std::uint64_t>& extent) {
  std::vector<Block> out;
  for (auto& block : blocks) {
    if (!out.empty()) {
      Block& last = out.back();
      if (rows ? continues_rows(last, block, extent) : continues_line(last, block)) {
        append_values(last, block, rows ? 0 : last.count.size() - 1);
        continue;
      }
    }
    out.push_back(std::move(block));
  }
  return out;
}

}  // namespace

std::vector<Block> merge_touching_blocks(std::vector<Block> blocks, const std::vector<std::uint64_t>& extent) {
  if (blocks.size() < 2 || blocks.front().count.empty()) return blocks;
  // Stable: of two blocks at one offset, the later stays later and so is written last.
  std::stable_sort(blocks.begin(), blocks.end(), [](const Block& a, const Block& b) { return a.offset < b.offset; });
  return merge_pass(merge_pass(std::move(blocks), false, extent), true, extent);
}

}  // namespace pbrfit::store
