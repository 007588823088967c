#include "pbrfit/store/block_codec.hpp"

namespace pbrfit::store {

namespace {

constexpr std::uint64_t max_elements_per_block = std::uint64_t(1) << 32;


void put_number(ByteWriter& out, ValueType type, const Number& number) {
  if (type == ValueType::f32) out.put(float(number.real()));
  else if (type == ValueType::f64) out.put(number.real());
  else if (is_signed_integer(type)) out.put_signed_varint(number.signed_value());
  else out.put_varint(number.unsigned_value());
}

Number get_number(ByteReader& in, ValueType type) {
  if (type == ValueType::f32) return double(in.get<float>());
  if (type == ValueType::f64) return in.get<double>();
  const std::size_t start = in.offset();
  const Number number = is_signed_integer(type) ? Number(in.get_signed_varint()) : Number(in.get_varint());
  if (!holds(type, number)) throw ByteFormatError(start, std::string("value out of range for ") + type_name(type));
  return number;
}

}  // namespace

BlockCodec::BlockCodec(const ResultLayout& layout) : index_(layout) {
  for (const auto& group : layout.groups) {
    for (const auto& table : group.tables) {
      std::vector<std::uint64_t> extent;
      for (std::size_t d = 0; d < table.axes.size(); ++d)
        extent.push_back(d == 0 && table.growing ? 0 : group.axis(table.axes[d]).values.size());
      extents_.push_back(std::move(extent));
      number_types_.push_back(number_types(table));
    }
  }
}

void BlockCodec::encode(ByteWriter& out, const Block& block) const {
  const std::uint32_t t = index_.find(block.group, block.table);
  check_block(block, index_.table(t));
  out.put_varint(t);
  for (const auto o : block.offset) out.put_varint(o);
  for (const auto c : block.count) out.put_varint(c);
  const auto& types = number_types_[t];
  for (std::size_t i = 0; i < block.values.size(); ++i) put_number(out, types[i % types.size()], block.values[i]);
  for (const auto& text : block.texts) out.put_string(text);
}

Block BlockCodec::decode(ByteReader& in) const {
  const std::size_t start = in.offset();
  const auto t = in.get_varint();
  if (t >= index_.size()) throw ByteFormatError(start, "block names table " + std::to_string(t) + ", which the job does not have");
  const Table& table = index_.table(std::uint32_t(t));
  const auto& extent = extents_[t];
  Block block{index_.group_of(std::uint32_t(t)), table.name, std::vector<std::uint64_t>(extent.size()),
              std::vector<std::uint64_t>(extent.size()), {}, {}};
  for (auto& o : block.offset) o = in.get_varint();
  for (auto& c : block.count) c = in.get_varint();
  std::uint64_t elements = 1;
  for (std::size_t d = 0; d < extent.size(); ++d) {
    const bool unbounded = extent[d] == 0 && d == 0 && table.growing;
    const std::uint64_t limit = unbounded ? max_elements_per_block : extent[d];
    if (block.count[d] > limit || block.offset[d] > limit - block.count[d])
      throw ByteFormatError(start, "block of " + block.group + "/" + block.table + " lies outside the table");
    elements *= block.count[d];
    if (elements > max_elements_per_block) throw ByteFormatError(start, "block is implausibly large");
  }
  const auto& types = number_types_[t];
  const std::uint64_t numbers = elements * table.numbers_per_element();
  if (numbers > in.remaining()) throw ByteFormatError(in.offset(), "block values exceed the data");  // a byte each at least
  block.values.resize(numbers);
  for (std::size_t i = 0; i < numbers; ++i) block.values[i] = get_number(in, types[i % types.size()]);
  const std::uint64_t texts = elements * table.texts_per_element();
  if (texts > in.remaining() / sizeof(std::uint64_t)) throw ByteFormatError(in.offset(), "block texts exceed the data");
  block.texts.resize(texts);
  for (auto& text : block.texts) text = in.get_string();
  return block;
}

}  // namespace pbrfit::store
