#include "pbrfit/texture/npy.hpp"

#include "encoding.hpp"

namespace pbrfit::texture {
namespace {

using namespace detail;

constexpr std::size_t magic_bytes = 10, alignment = 64;

std::string shape(const Texture& t) {
  std::string text = "(";
  if (t.layers > 1) text += std::to_string(t.layers) + ", ";
  if (t.depth > 1) text += std::to_string(t.depth) + ", ";
  return text + std::to_string(t.height) + ", " + std::to_string(t.width) + ", " + std::to_string(t.channels.size()) +
         ")";
}

}  // namespace

Bytes encode_npy(const Texture& t, Precision precision) {
  check_texture(t, "npy");
  if (t.levels > 1) refuse("npy", "holds one mip level, not " + std::to_string(t.levels));
  std::string header = std::string("{'descr': '") + (precision == Precision::f32 ? "<f4" : "<f2") +
                       "', 'fortran_order': False, 'shape': " + shape(t) + ", }";
  header.append((alignment - (magic_bytes + header.size() + 1) % alignment) % alignment, ' ');
  header += '\n';
  Bytes out = as_bytes("\x93NUMPY");
  put_u8(out, 1);
  put_u8(out, 0);
  put_u16(out, std::uint16_t(header.size()));
  put_text(out, header);
  for (const double v : t.values) {
    if (precision == Precision::f32) put_u32(out, float_bits(v));
    else put_u16(out, half_bits(v));
  }
  return out;
}

}  // namespace pbrfit::texture
