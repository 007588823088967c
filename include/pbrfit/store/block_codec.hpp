#pragma once
// Blocks as bytes, for checkpoints and the block journal. A block names its table by its index in the
// layout; its table index, offsets and counts are variable-length integers (a cell costs a few bytes
// beside its value); numbers are stored in the table's own type (float32 values lose nothing the result file
// would not lose; integers are variable-length, zigzag-coded when signed), texts as strings. Decoding checks everything against the layout, so a crafted or
// damaged file can name no table, dimension or position the layout does not have.
#include "pbrfit/core/bytes.hpp"
#include "pbrfit/store/result_layout.hpp"

namespace pbrfit::store {

class BlockCodec {
 public:
  explicit BlockCodec(const ResultLayout& layout);

  void encode(ByteWriter& out, const Block& block) const;
  // Throws ByteFormatError (with the offset) for data that does not describe a block of the layout.
  Block decode(ByteReader& in) const;

  const TableIndex& tables() const { return index_; }

 private:
  // Extent of each dimension of a fixed table (0 for the growing first dimension: unbounded).
  std::vector<std::vector<std::uint64_t>> extents_;
  // Per table, the type of each number of an element.
  std::vector<std::vector<ValueType>> number_types_;
  TableIndex index_;
};

}  // namespace pbrfit::store
