#pragma once
// Blocks waiting to be written, kept encoded (block_codec.hpp): a few bytes a value instead of a heap
// object a block, so a million finished items waiting for the next flush cost little. Private to the
// runtime.
#include <cstdint>
#include <vector>

#include "pbrfit/store/block_codec.hpp"

namespace pbrfit::runtime {

class PendingBlocks {
 public:
  void add(const store::BlockCodec& codec, const store::Block& block);
  // Adds `block` to both, encoded and checked once (the unflushed and the unjournaled blocks).
  static void add_to_both(const store::BlockCodec& codec, const store::Block& block, PendingBlocks& a, PendingBlocks& b);
  std::uint64_t count() const { return count_; }
  const Bytes& bytes() const { return out_.bytes(); }
  std::vector<store::Block> decode(const store::BlockCodec& codec) const;
  void clear() { *this = PendingBlocks{}; }

 private:
  ByteWriter out_;
  std::uint64_t count_ = 0;
};

}  // namespace pbrfit::runtime
