#include "pbrfit/texture/radiance_hdr.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "encoding.hpp"

namespace pbrfit::texture {
namespace {

using namespace detail;

constexpr std::size_t longest_line = 1000;

void check_values(const Texture& t) {
  for (std::size_t i = 0; i < t.values.size(); ++i) {
    const double v = t.values[i];
    if (!std::isfinite(v)) refuse("hdr", "value " + number(v) + " at " + texel_of(t, i) + " is not finite");
    if (v < 0) refuse("hdr", "value " + number(v) + " at " + texel_of(t, i) + " is negative; RGBE holds values >= 0");
    if (v >= 0x1p127) refuse("hdr", "value " + number(v) + " at " + texel_of(t, i) + " is not below 2^127");
  }
}

void put_rgbe(Bytes& out, const double (&rgb)[3]) {
  const double largest = std::max({rgb[0], rgb[1], rgb[2]});
  if (largest < 1e-32) return put_zeros(out, 4);
  int exponent = 0;
  std::frexp(largest, &exponent);  // largest in [2^(exponent-1), 2^exponent)
  const double scale = std::ldexp(256.0, -exponent);
  for (const double v : rgb) put_u8(out, std::uint8_t(std::min(255.0, std::floor(v * scale))));
  put_u8(out, std::uint8_t(exponent + 128));
}

}  // namespace

Bytes encode_hdr(const Texture& t) {
  check_texture(t, "hdr");
  if (t.channels.size() > 3) refuse("hdr", "holds 3 channels, not " + std::to_string(t.channels.size()));
  require_one_image(t, "hdr");
  check_values(t);
  Bytes out;
  put_text(out, "#?RADIANCE\n");
  for (const auto& [key, value] : text_entries(t)) {
    const std::string line = "# pbrfit:" + key + ": " + quoted(value) + "\n";
    if (line.size() > longest_line)
      refuse("hdr", "the header line of \"" + key + "\" has " + std::to_string(line.size()) + " bytes; readers take " +
                        std::to_string(longest_line) + " at most");
    put_text(out, line);
  }
  put_text(out, "FORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(t.height) + " +X " + std::to_string(t.width) + "\n");
  const std::size_t channels = t.channels.size();
  for (std::size_t i = 0; i < t.values.size(); i += channels) {
    double rgb[3] = {0, 0, 0};
    for (std::size_t c = 0; c < channels; ++c) rgb[c] = t.values[i + c] == 0 ? 0.0 : t.values[i + c];
    put_rgbe(out, rgb);
  }
  return out;
}

}  // namespace pbrfit::texture
