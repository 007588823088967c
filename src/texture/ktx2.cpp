#include "pbrfit/texture/ktx2.hpp"

#include <algorithm>
#include <numeric>

#include "encoding.hpp"

namespace pbrfit::texture {
namespace {

using namespace detail;

constexpr std::uint8_t identifier[12] = {0xAB, 0x4B, 0x54, 0x58, 0x20, 0x32, 0x30, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A};
constexpr std::size_t header_bytes = 12 + 9 * 4 + 4 * 4 + 2 * 8, level_entry_bytes = 3 * 8;
constexpr std::uint32_t model_rgbsda = 1, primaries_bt709 = 1, transfer_linear = 1, version_1_3 = 2;
constexpr std::uint8_t datatype_signed = 0x40, datatype_float = 0x80;
constexpr std::uint8_t channel_ids[4] = {0, 1, 2, 15};
constexpr std::uint32_t minus_one_f = 0xBF800000, one_f = 0x3F800000;

std::uint32_t vk_format(std::size_t channels, Precision precision) {
  constexpr std::uint32_t half[] = {76, 83, 90, 97}, single[] = {100, 103, 106, 109};
  return (precision == Precision::f32 ? single : half)[channels - 1];
}

void put_dfd(Bytes& out, std::size_t channels, std::size_t component_bytes) {
  const auto block_size = std::uint32_t(24 + 16 * channels);
  put_u32(out, 4 + block_size);  // dfdTotalSize
  put_u32(out, 0);               // vendorId KHR (17 bits), descriptorType basic (15 bits)
  put_u32(out, version_1_3 | block_size << 16);
  put_u32(out, model_rgbsda | primaries_bt709 << 8 | transfer_linear << 16);  // flags 0: straight alpha
  put_u32(out, 0);                                                            // texelBlockDimension 1x1x1x1
  put_u32(out, std::uint32_t(channels * component_bytes));                    // bytesPlane0
  put_u32(out, 0);                                                            // bytesPlane4..7
  for (std::size_t c = 0; c < channels; ++c) {
    const auto bits = std::uint32_t(8 * component_bytes);
    const std::uint32_t type = channel_ids[c] | datatype_signed | datatype_float;
    put_u32(out, std::uint32_t(c) * bits | (bits - 1) << 16 | type << 24);
    put_u32(out, 0);  // samplePosition
    put_u32(out, minus_one_f);
    put_u32(out, one_f);
  }
}

void put_key_values(Bytes& out, const Texture& t) {
  const char* orientation = t.depth > 1 ? "rdi" : t.height == 1 ? "r" : "rd";
  std::vector<std::pair<std::string, std::string>> entries = {{"KTXorientation", orientation}, {"KTXwriter", "pbrfit"}};
  for (const auto& [key, value] : text_entries(t)) entries.emplace_back("pbrfit:" + key, value);
  std::sort(entries.begin(), entries.end());  // std::string compares bytewise (char_traits<char>::compare)
  for (const auto& [key, value] : entries) {
    const std::size_t length = key.size() + 1 + value.size() + 1;
    put_u32(out, std::uint32_t(length));
    put_text(out, key);
    put_u8(out, 0);
    put_text(out, value);
    put_u8(out, 0);
    put_zeros(out, (4 - length % 4) % 4);
  }
}

void put_level(Bytes& out, const Texture& t, std::size_t level, Precision precision) {
  const std::size_t begin = level_offset(t, level, 0), end = level_offset(t, level + 1, 0);
  for (std::size_t i = begin; i < end; ++i) {
    if (precision == Precision::f32) put_u32(out, float_bits(t.values[i]));
    else put_u16(out, half_bits(t.values[i]));
  }
}

}  // namespace

Bytes encode_ktx2(const Texture& t, Precision precision) {
  check_texture(t, "ktx2");
  const std::size_t channels = t.channels.size(), component = precision == Precision::f32 ? 4 : 2;
  Bytes out;
  for (std::uint8_t b : identifier) put_u8(out, b);
  put_u32(out, vk_format(channels, precision));
  put_u32(out, std::uint32_t(component));
  put_u32(out, std::uint32_t(t.width));
  put_u32(out, t.height == 1 && t.depth == 1 ? 0 : std::uint32_t(t.height));
  put_u32(out, t.depth > 1 ? std::uint32_t(t.depth) : 0);
  put_u32(out, t.layers > 1 ? std::uint32_t(t.layers) : 0);
  put_u32(out, 1);  // faceCount
  put_u32(out, std::uint32_t(t.levels));
  put_u32(out, 0);  // supercompressionScheme
  const std::size_t index_at = out.size();
  put_zeros(out, 4 * 4 + 2 * 8);  // the index, filled in below
  const std::size_t level_index_at = out.size();
  put_zeros(out, t.levels * level_entry_bytes);
  const std::size_t dfd_at = out.size();
  put_dfd(out, channels, component);
  const std::size_t kvd_at = out.size();
  put_key_values(out, t);
  set_u32(out, index_at, std::uint32_t(dfd_at));
  set_u32(out, index_at + 4, std::uint32_t(kvd_at - dfd_at));
  set_u32(out, index_at + 8, std::uint32_t(kvd_at));
  set_u32(out, index_at + 12, std::uint32_t(out.size() - kvd_at));
  const std::size_t alignment = std::lcm(channels * component, std::size_t(4));
  for (std::size_t level = t.levels; level-- > 0;) {
    put_zeros(out, (alignment - out.size() % alignment) % alignment);
    const std::size_t start = out.size();
    put_level(out, t, level, precision);
    const std::size_t entry = level_index_at + level * level_entry_bytes;
    set_u64(out, entry, start);
    set_u64(out, entry + 8, out.size() - start);
    set_u64(out, entry + 16, out.size() - start);
  }
  static_assert(header_bytes == 80);
  return out;
}

}  // namespace pbrfit::texture
