#include "encoding.hpp"

#include <bit>
#include <cstdio>
#include <stdexcept>

#include <Imath/half.h>

namespace pbrfit::texture::detail {

void refuse(std::string_view format, const std::string& why) {
  throw std::invalid_argument(std::string(format) + ": " + why);
}

void check_texture(const Texture& t, std::string_view format) {
  try {
    validate(t);
  } catch (const std::invalid_argument& e) {
    refuse(format, e.what());
  }
}

void require_one_image(const Texture& t, std::string_view format) {
  if (t.levels > 1) refuse(format, "holds one 2D image, not " + std::to_string(t.levels) + " mip levels");
  if (t.layers > 1) refuse(format, "holds one 2D image, not " + std::to_string(t.layers) + " array layers");
  if (t.depth > 1) refuse(format, "holds one 2D image, not a volume of depth " + std::to_string(t.depth));
}

std::string texel_of(const Texture& t, std::size_t index) {
  std::size_t level = 0;
  while (level + 1 < t.levels && level_offset(t, level + 1, 0) <= index) ++level;
  const std::size_t per_layer = layer_value_count(t, level);
  std::size_t rest = index - level_offset(t, level, 0);
  const std::size_t layer = rest / per_layer;
  rest %= per_layer;
  const std::size_t c = rest % t.channels.size(), texel = rest / t.channels.size();
  const std::size_t w = level_width(t, level), h = level_height(t, level);
  std::string where = "level " + std::to_string(level) + ", ";
  if (t.layers > 1) where += "layer " + std::to_string(layer) + ", ";
  where += "texel (" + std::to_string(texel % w) + ", " + std::to_string(texel / w % h);
  if (t.depth > 1) where += ", " + std::to_string(texel / w / h);
  return where + "), channel " + t.channels[c];
}

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

float to_float(double v) { return static_cast<float>(v); }
std::uint32_t float_bits(double v) { return std::bit_cast<std::uint32_t>(static_cast<float>(v)); }
std::uint16_t half_bits(double v) { return Imath::half(static_cast<float>(v)).bits(); }
float half_rounded(double v) { return float(Imath::half(static_cast<float>(v))); }

std::vector<std::pair<std::string, std::string>> text_entries(const Texture& t) {
  std::string channels;
  for (const std::string& c : t.channels) channels += (channels.empty() ? "" : ",") + c;
  std::vector<std::pair<std::string, std::string>> entries = {{"name", t.name}, {"channels", channels}};
  entries.insert(entries.end(), t.metadata.begin(), t.metadata.end());
  return entries;
}

std::string quoted(std::string_view text) {
  std::string out = "\"";
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '\\' || c == '"') out += '\\', out += ch;
    else if (c == '\n') out += "\\n";
    else if (c == '\r') out += "\\r";
    else if (c == '\t') out += "\\t";
    else if (c >= 0x20 && c < 0x7f) out += ch;
    else {
      char hex[5];
      std::snprintf(hex, sizeof hex, "\\x%02x", unsigned(c));
      out += hex;
    }
  }
  return out + "\"";
}

void put_u8(Bytes& out, std::uint8_t v) { out.push_back(std::byte(v)); }
void put_u16(Bytes& out, std::uint16_t v) {
  for (int k = 0; k < 2; ++k) out.push_back(std::byte(v >> (8 * k)));
}
void put_u32(Bytes& out, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) out.push_back(std::byte(v >> (8 * k)));
}
void put_u64(Bytes& out, std::uint64_t v) {
  for (int k = 0; k < 8; ++k) out.push_back(std::byte(v >> (8 * k)));
}
void put_text(Bytes& out, std::string_view text) {
  for (const char c : text) out.push_back(std::byte(c));
}
void put_zeros(Bytes& out, std::size_t count) { out.insert(out.end(), count, std::byte(0)); }
void set_u32(Bytes& out, std::size_t at, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) out.at(at + k) = std::byte(v >> (8 * k));
}
void set_u64(Bytes& out, std::size_t at, std::uint64_t v) {
  for (int k = 0; k < 8; ++k) out.at(at + k) = std::byte(v >> (8 * k));
}
Bytes as_bytes(std::string_view text) {
  Bytes out;
  put_text(out, text);
  return out;
}

}  // namespace pbrfit::texture::detail
