// DDS with the DX10 extension, byte by byte: no independent reader of float DDS is at hand, so every header
// field is checked against the value Microsoft's DDS documentation prescribes for each kind of texture (the
// numbers below are the documentation's), and the texels against the input in DDS's order (each layer with
// all its mip levels, the largest first).
#include <catch2/catch_test_macros.hpp>

#include "pbrfit/texture/dds.hpp"
#include "texture_test_support.hpp"

using namespace pbrfit;
using namespace pbrfit::texture;
using testing::u32;

namespace {

struct Expected {
  std::uint32_t flags, height, width, pitch, depth, mip_count, caps, caps2;
  std::uint32_t dxgi_format, dimension, array_size, alpha_mode;
};

void check_header(const Bytes& b, const Expected& e) {
  REQUIRE(b.size() >= 148);
  CHECK(testing::text(b, 0, 4) == "DDS ");
  CHECK(u32(b, 4) == 124);  // dwSize
  CHECK(u32(b, 8) == e.flags);
  CHECK(u32(b, 12) == e.height);
  CHECK(u32(b, 16) == e.width);
  CHECK(u32(b, 20) == e.pitch);  // dwPitchOrLinearSize
  CHECK(u32(b, 24) == e.depth);
  CHECK(u32(b, 28) == e.mip_count);
  for (std::size_t k = 0; k < 11; ++k) CHECK(u32(b, 32 + 4 * k) == 0);  // dwReserved1
  CHECK(u32(b, 76) == 32);                                              // ddspf.dwSize
  CHECK(u32(b, 80) == 0x4);                                             // DDPF_FOURCC
  CHECK(testing::text(b, 84, 4) == "DX10");
  for (std::size_t k = 0; k < 5; ++k) CHECK(u32(b, 88 + 4 * k) == 0);  // bit count, masks
  CHECK(u32(b, 108) == e.caps);
  CHECK(u32(b, 112) == e.caps2);
  CHECK(u32(b, 116) == 0);  // dwCaps3
  CHECK(u32(b, 120) == 0);  // dwCaps4
  CHECK(u32(b, 124) == 0);  // dwReserved2
  CHECK(u32(b, 128) == e.dxgi_format);
  CHECK(u32(b, 132) == e.dimension);
  CHECK(u32(b, 136) == 0);  // miscFlag: not a cube map
  CHECK(u32(b, 140) == e.array_size);
  CHECK(u32(b, 144) == e.alpha_mode);  // miscFlags2
}

// The texels in DDS order, as the bits the file must hold (f16 RGB gets A = 1.0).
std::vector<std::uint32_t> expected_texels(const Texture& t, Precision precision) {
  std::vector<std::uint32_t> out;
  const std::size_t channels = t.channels.size();
  for (std::size_t layer = 0; layer < t.layers; ++layer)
    for (std::size_t level = 0; level < t.levels; ++level) {
      const std::size_t begin = level_offset(t, level, layer);
      for (std::size_t i = begin; i < begin + layer_value_count(t, level); i += channels) {
        for (std::size_t c = 0; c < channels; ++c)
          out.push_back(precision == Precision::f32 ? testing::f32_bits(t.values[i + c])
                                                    : testing::f16_bits(t.values[i + c]));
        if (precision == Precision::f16 && channels == 3) out.push_back(0x3c00);
      }
    }
  return out;
}

void check_texels(const Bytes& b, const Texture& t, Precision precision) {
  const std::vector<std::uint32_t> expected = expected_texels(t, precision);
  const std::size_t size = precision == Precision::f32 ? 4 : 2;
  REQUIRE(b.size() == 148 + expected.size() * size);
  std::size_t mismatches = 0;
  for (std::size_t k = 0; k < expected.size(); ++k) {
    const std::uint32_t got = size == 4 ? u32(b, 148 + 4 * k) : testing::u16(b, 148 + 2 * k);
    mismatches += got != expected[k];
  }
  CHECK(mismatches == 0);
}

constexpr std::uint32_t texture_flags = 0x1 | 0x2 | 0x4 | 0x1000 | 0x8;  // CAPS HEIGHT WIDTH PIXELFORMAT PITCH
constexpr std::uint32_t mipmapcount = 0x20000, depth_flag = 0x800000;
constexpr std::uint32_t caps_texture = 0x1000, caps_complex = 0x8, caps_mipmap = 0x400000, caps2_volume = 0x200000;

}  // namespace

TEST_CASE("DDS: a 2D RGBA32F texture") {
  const Texture t = testing::sample(5, 3, 4);
  const Bytes b = encode_dds(t, Precision::f32);
  // DXGI_FORMAT_R32G32B32A32_FLOAT 2, TEXTURE2D 3, DDS_ALPHA_MODE_CUSTOM 4 (alpha is data).
  check_header(b, {texture_flags, 3, 5, 5 * 16, 0, 0, caps_texture, 0, 2, 3, 1, 4});
  check_texels(b, t, Precision::f32);
}

TEST_CASE("DDS: an RG32F texture") {
  const Texture t = testing::sample(7, 2, 2);
  const Bytes b = encode_dds(t, Precision::f32);
  check_header(b, {texture_flags, 2, 7, 7 * 8, 0, 0, caps_texture, 0, 16, 3, 1, 0});
  check_texels(b, t, Precision::f32);
}

TEST_CASE("DDS: R32F and RGB32F, and R16F and RG16F") {
  const Texture r = testing::sample(3, 3, 1), rgb = testing::sample(3, 2, 3), rg = testing::sample(2, 2, 2);
  check_header(encode_dds(r, Precision::f32), {texture_flags, 3, 3, 12, 0, 0, caps_texture, 0, 41, 3, 1, 0});
  check_texels(encode_dds(r, Precision::f32), r, Precision::f32);
  check_header(encode_dds(rgb, Precision::f32), {texture_flags, 2, 3, 36, 0, 0, caps_texture, 0, 6, 3, 1, 0});
  check_texels(encode_dds(rgb, Precision::f32), rgb, Precision::f32);
  check_header(encode_dds(r, Precision::f16), {texture_flags, 3, 3, 6, 0, 0, caps_texture, 0, 54, 3, 1, 0});
  check_texels(encode_dds(r, Precision::f16), r, Precision::f16);
  check_header(encode_dds(rg, Precision::f16), {texture_flags, 2, 2, 8, 0, 0, caps_texture, 0, 34, 3, 1, 0});
  check_texels(encode_dds(rg, Precision::f16), rg, Precision::f16);
}

TEST_CASE("DDS: RGBA16F, and 3-channel half widened to RGBA16F with A = 1, alpha mode opaque") {
  const Texture rgba = testing::sample(4, 4, 4), rgb = testing::sample(6, 2, 3);
  check_header(encode_dds(rgba, Precision::f16), {texture_flags, 4, 4, 32, 0, 0, caps_texture, 0, 10, 3, 1, 4});
  check_texels(encode_dds(rgba, Precision::f16), rgba, Precision::f16);
  // DXGI_FORMAT_R16G16B16A16_FLOAT 10; 8 bytes a texel; DDS_ALPHA_MODE_OPAQUE 3.
  check_header(encode_dds(rgb, Precision::f16), {texture_flags, 2, 6, 48, 0, 0, caps_texture, 0, 10, 3, 1, 3});
  check_texels(encode_dds(rgb, Precision::f16), rgb, Precision::f16);
}

TEST_CASE("DDS: a texture array: arraySize, COMPLEX, each layer's surface in turn") {
  const Texture t = testing::sample(4, 2, 2, testing::Values::awkward, 1, 3);
  const Bytes b = encode_dds(t, Precision::f32);
  check_header(b, {texture_flags, 2, 4, 32, 0, 0, caps_texture | caps_complex, 0, 16, 3, 3, 0});
  check_texels(b, t, Precision::f32);
}

TEST_CASE("DDS: mips, in an array: MIPMAPCOUNT, COMPLEX | MIPMAP, each layer with all its levels") {
  const Texture t = testing::sample(8, 4, 4, testing::Values::awkward, 1, 2, 4);
  const Bytes b = encode_dds(t, Precision::f16);
  check_header(
      b, {texture_flags | mipmapcount, 4, 8, 64, 0, 4, caps_texture | caps_complex | caps_mipmap, 0, 10, 3, 2, 4});
  check_texels(b, t, Precision::f16);
}

TEST_CASE("DDS: a volume with mips: DEPTH, dwDepth, VOLUME, TEXTURE3D, all slices of a level together") {
  const Texture t = testing::sample(4, 2, 1, testing::Values::awkward, 8, 1, 4);
  const Bytes b = encode_dds(t, Precision::f32);
  check_header(b, {texture_flags | mipmapcount | depth_flag, 2, 4, 16, 8, 4, caps_texture | caps_complex | caps_mipmap,
                   caps2_volume, 41, 4, 1, 0});
  check_texels(b, t, Precision::f32);
  const Texture flat_volume = testing::sample(2, 2, 2, testing::Values::awkward, 3);
  check_header(encode_dds(flat_volume, Precision::f32),
               {texture_flags | depth_flag, 2, 2, 16, 3, 0, caps_texture | caps_complex, caps2_volume, 16, 4, 1, 0});
}

TEST_CASE("DDS: a texture of one row is TEXTURE1D") {
  const Texture t = testing::sample(16, 1, 2, testing::Values::awkward, 1, 1, 5);
  const Bytes b = encode_dds(t, Precision::f32);
  check_header(
      b, {texture_flags | mipmapcount, 1, 16, 128, 0, 5, caps_texture | caps_complex | caps_mipmap, 0, 16, 2, 1, 0});
  check_texels(b, t, Precision::f32);
}
