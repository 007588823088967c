#include "pending_blocks.hpp"

namespace pbrfit::runtime {

void PendingBlocks::add(const store::BlockCodec& codec, const store::Block& block) {
  codec.encode(out_, block);
  ++count_;
}

void PendingBlocks::add_to_both(const store::BlockCodec& codec, const store::Block& block, PendingBlocks& a,
                                PendingBlocks& b) {
  const std::size_t from = a.out_.bytes().size();
  a.add(codec, block);
  b.out_.put_raw(std::span<const std::byte>(a.out_.bytes()).subspan(from));
  ++b.count_;
}

std::vector<store::Block> PendingBlocks::decode(const store::BlockCodec& codec) const {
  std::vector<store::Block> blocks;
  blocks.reserve(count_);
  ByteReader in(out_.bytes());
  for (std::uint64_t i = 0; i < count_; ++i) blocks.push_back(codec.decode(in));
  return blocks;
}

}  // namespace pbrfit::runtime
