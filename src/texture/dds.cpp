#include "pbrfit/texture/dds.hpp"

#include "encoding.hpp"

namespace pbrfit::texture {
namespace {

using namespace detail;

constexpr std::uint32_t ddsd_caps = 0x1, ddsd_height = 0x2, ddsd_width = 0x4, ddsd_pitch = 0x8,
                        ddsd_pixelformat = 0x1000, ddsd_mipmapcount = 0x20000, ddsd_depth = 0x800000;
constexpr std::uint32_t ddpf_fourcc = 0x4;
constexpr std::uint32_t ddscaps_complex = 0x8, ddscaps_texture = 0x1000, ddscaps_mipmap = 0x400000;
constexpr std::uint32_t ddscaps2_volume = 0x200000;
constexpr std::uint32_t dimension_1d = 2, dimension_2d = 3, dimension_3d = 4;
constexpr std::uint32_t alpha_unknown = 0, alpha_opaque = 3, alpha_custom = 4;

std::uint32_t dxgi_format(std::size_t channels, Precision precision) {
  if (precision == Precision::f32) {
    constexpr std::uint32_t formats[] = {41, 16, 6, 2};
    return formats[channels - 1];
  }
  constexpr std::uint32_t formats[] = {54, 34, 10, 10};
  return formats[channels - 1];
}

std::uint32_t fourcc(const char (&code)[5]) {
  return std::uint32_t(std::uint8_t(code[0])) | std::uint32_t(std::uint8_t(code[1])) << 8 |
         std::uint32_t(std::uint8_t(code[2])) << 16 | std::uint32_t(std::uint8_t(code[3])) << 24;
}

void put_header(Bytes& out, const Texture& t, std::size_t stored_channels, Precision precision) {
  const bool mips = t.levels > 1, volume = t.depth > 1;
  const std::size_t texel_bytes = stored_channels * (precision == Precision::f32 ? 4 : 2);
  put_text(out, "DDS ");
  put_u32(out, 124);
  put_u32(out, ddsd_caps | ddsd_height | ddsd_width | ddsd_pixelformat | ddsd_pitch | (mips ? ddsd_mipmapcount : 0) |
                   (volume ? ddsd_depth : 0));
  put_u32(out, std::uint32_t(t.height));
  put_u32(out, std::uint32_t(t.width));
  put_u32(out, std::uint32_t(t.width * texel_bytes));
  put_u32(out, volume ? std::uint32_t(t.depth) : 0);
  put_u32(out, mips ? std::uint32_t(t.levels) : 0);
  put_zeros(out, 11 * 4);  // dwReserved1
  put_u32(out, 32);        // ddspf.dwSize
  put_u32(out, ddpf_fourcc);
  put_u32(out, fourcc("DX10"));
  put_zeros(out, 5 * 4);  // dwRGBBitCount and the four masks
  const bool complex = mips || volume || t.layers > 1;
  put_u32(out, ddscaps_texture | (complex ? ddscaps_complex : 0) | (mips ? ddscaps_mipmap : 0));
  put_u32(out, volume ? ddscaps2_volume : 0);
  put_zeros(out, 3 * 4);  // dwCaps3, dwCaps4, dwReserved2
  // DDS_HEADER_DXT10
  put_u32(out, dxgi_format(t.channels.size(), precision));
  put_u32(out, volume ? dimension_3d : t.height == 1 ? dimension_1d : dimension_2d);
  put_u32(out, 0);
  put_u32(out, std::uint32_t(t.layers));
  put_u32(out, t.channels.size() == 4 ? alpha_custom : stored_channels == 4 ? alpha_opaque : alpha_unknown);
}

}  // namespace

Bytes encode_dds(const Texture& t, Precision precision) {
  check_texture(t, "dds");
  const std::size_t channels = t.channels.size();
  const std::size_t stored = precision == Precision::f16 && channels == 3 ? 4 : channels;
  Bytes out;
  put_header(out, t, stored, precision);
  for (std::size_t layer = 0; layer < t.layers; ++layer) {
    for (std::size_t level = 0; level < t.levels; ++level) {
      const std::size_t begin = level_offset(t, level, layer), end = begin + layer_value_count(t, level);
      for (std::size_t i = begin; i < end; i += channels) {
        for (std::size_t c = 0; c < channels; ++c) {
          if (precision == Precision::f32) put_u32(out, float_bits(t.values[i + c]));
          else put_u16(out, half_bits(t.values[i + c]));
        }
        if (stored > channels) put_u16(out, half_one);
      }
    }
  }
  return out;
}

}  // namespace pbrfit::texture
