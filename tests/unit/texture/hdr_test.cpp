// Radiance HDR read back by stb_image (its own RGBE decoding: q 2^(E-8)), every component within RGBE's
// documented quantization of the input: v - 2^(E-8) < v' <= v, with 2^(E-1) <= max(R, G, B) < 2^E.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <cmath>

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_HDR
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wunused-but-set-variable"
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

#include "pbrfit/texture/radiance_hdr.hpp"
#include "texture_test_support.hpp"

using namespace pbrfit;
using namespace pbrfit::texture;
using Catch::Matchers::Equals;

namespace {

void check_hdr(const Texture& t) {
  const Bytes b = encode_hdr(t);
  int width = 0, height = 0, components = 0;
  float* pixels = stbi_loadf_from_memory(reinterpret_cast<const stbi_uc*>(b.data()), int(b.size()), &width, &height,
                                         &components, 3);
  INFO((stbi_failure_reason() ? stbi_failure_reason() : ""));
  REQUIRE(pixels != nullptr);
  CHECK(width == int(t.width));
  CHECK(height == int(t.height));
  const std::size_t channels = t.channels.size();
  std::size_t outside = 0, padding = 0;
  for (std::size_t texel = 0; texel < t.width * t.height; ++texel) {
    double largest = 0;
    for (std::size_t c = 0; c < channels; ++c) largest = std::max(largest, t.values[texel * channels + c]);
    int exponent = 0;
    std::frexp(largest, &exponent);
    const double step = largest < 1e-32 ? 1e-32 : std::ldexp(1.0, exponent - 8);
    for (std::size_t c = 0; c < 3; ++c) {
      const double got = pixels[3 * texel + c];
      if (c >= channels) {
        padding += got != 0.0;
        continue;
      }
      const double v = t.values[texel * channels + c];
      outside += !(got <= v && got > v - step);
    }
  }
  stbi_image_free(pixels);
  CHECK(outside == 0);
  CHECK(padding == 0);
}

}  // namespace

TEST_CASE("HDR: stb_image reads 1, 2 and 3 channels within RGBE's quantization") {
  for (std::size_t channels = 1; channels <= 3; ++channels)
    for (const std::size_t width : {std::size_t(5), std::size_t(64)})  // 64: where run-length scanlines could be
      check_hdr(testing::sample(width, 7, channels, testing::Values::positive, 1, 1, 1, unsigned(channels)));
}

TEST_CASE("HDR: the header holds the orientation, the format and the metadata as comments") {
  Texture t = testing::sample(3, 2, 3, testing::Values::positive);
  t.metadata = {{"source", "line one\nline \"two\""}};
  const Bytes b = encode_hdr(t);
  const std::string header = testing::text(b, 0, b.size() - 3 * 2 * 4);
  CHECK(header ==
        "#?RADIANCE\n# pbrfit:name: \"sample 3x2\"\n# pbrfit:channels: \"R,G,B\"\n"
        "# pbrfit:source: \"line one\\nline \\\"two\\\"\"\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 3\n");
  check_hdr(t);
}

TEST_CASE("HDR: RGBE bytes: 8-bit mantissas of the largest component's exponent, black below 1e-32") {
  Texture t;
  t.width = 4;
  t.channels = {"R", "G", "B"};
  t.values = {1.0, 0.5, 0.25, 3.0, 0.0, 1e-3, 1e-33, 0.0, 0.0, 0.999, 0.0, 0.0};
  const Bytes b = encode_hdr(t);
  const std::size_t at = b.size() - 16;
  const auto pixel = [&](std::size_t k) {
    std::vector<int> p;
    for (std::size_t i = 0; i < 4; ++i) p.push_back(int(b[at + 4 * k + i]));
    return p;
  };
  CHECK(pixel(0) == std::vector<int>{128, 64, 32, 129});  // 1 = 128 / 256 * 2^1
  CHECK(pixel(1) == std::vector<int>{192, 0, 0, 130});    // 3 = 192 / 256 * 2^2; 1e-3 is below 1/256 of 4
  CHECK(pixel(2) == std::vector<int>{0, 0, 0, 0});
  CHECK(pixel(3) == std::vector<int>{255, 0, 0, 128});  // 0.999 * 256 = 255.7: truncated
}

TEST_CASE("HDR: refusals") {
  CHECK_THROWS_WITH(encode_hdr(testing::sample(4, 4, 4, testing::Values::positive)),
                    Equals("hdr: holds 3 channels, not 4"));
  CHECK_THROWS_WITH(encode_hdr(testing::sample(4, 4, 3, testing::Values::positive, 1, 1, 2)),
                    Equals("hdr: holds one 2D image, not 2 mip levels"));
  CHECK_THROWS_WITH(encode_hdr(testing::sample(4, 4, 3, testing::Values::positive, 1, 2)),
                    Equals("hdr: holds one 2D image, not 2 array layers"));
  Texture t = testing::sample(4, 3, 2, testing::Values::positive);
  t.values[2 * (4 * 2 + 1) + 1] = -0.5;
  t.values[2 * (4 * 2 + 3)] = -2.0;
  CHECK_THROWS_WITH(encode_hdr(t), Equals("hdr: value -0.5 at level 0, texel (1, 2), channel G is negative; RGBE "
                                          "holds values >= 0"));
  t = testing::sample(4, 3, 2, testing::Values::positive);
  t.values[5] = INFINITY;
  CHECK_THROWS_WITH(encode_hdr(t), Equals("hdr: value inf at level 0, texel (2, 0), channel G is not finite"));
  t.values[5] = 0x1p127;
  CHECK_THROWS_WITH(encode_hdr(t), Equals("hdr: value 1.7014118346046923e+38 at level 0, texel (2, 0), channel G is "
                                          "not below 2^127"));
  t.values[5] = -0.0;
  CHECK_NOTHROW(encode_hdr(t));
  t.metadata = {{"long", std::string(1000, 'x')}};
  CHECK_THROWS_WITH(encode_hdr(t),
                    Equals("hdr: the header line of \"long\" has 1018 bytes; readers take 1000 at most"));
}
