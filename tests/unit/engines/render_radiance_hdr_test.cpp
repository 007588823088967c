// Radiance .hdr bytes: known pixels, flat and run-length scanlines, round trips, and every kind of
// malformed or hostile input refused with the file's name and a byte offset.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_floating_point.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "pbrfit/core/error.hpp"
#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/render/radiance_hdr.hpp"

using namespace pbrfit::render;
using Catch::Matchers::ContainsSubstring;
using Catch::Matchers::WithinAbs;
using pbrfit::Bytes;
using pbrfit::RgbImage;

namespace {

const std::string header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n";

Bytes bytes_of(const std::string& text) {
  Bytes out;
  for (char c : text) out.push_back(std::byte(c));
  return out;
}

std::string text_of(const Bytes& bytes) { return {reinterpret_cast<const char*>(bytes.data()), bytes.size()}; }

RgbImage decoded(const std::string& text) { return decode_radiance_hdr(bytes_of(text), "sky.hdr"); }

std::string refusal(const std::string& text) {
  try {
    decoded(text);
  } catch (const pbrfit::InputError& e) {
    CHECK(e.where().file == "sky.hdr");
    CHECK(std::string(e.what()).starts_with("sky.hdr: error: "));
    return e.message();
  }
  return "(accepted)";
}

std::string pixel(int r, int g, int b, int e) { return {char(r), char(g), char(b), char(e)}; }

RgbImage gradient(std::size_t width, std::size_t height) {
  RgbImage image(width, height);
  for (std::size_t p = 0; p < image.pixels(); ++p) {
    const float v = (p / 3) % 5 == 0 ? 0.0f : std::ldexp(1.0f + float(p % 7) / 7.0f, int(p % 19) - 9);
    image.set(p, {v, 0.5f * v, (p / 11) % 2 ? 1000.0f : v});
  }
  return image;
}

}  // namespace

TEST_CASE("flat Radiance pixels decode as (m + 0.5) 2^(e - 136), black for e = 0") {
  const RgbImage image = decoded(header + "-Y 1 +X 2\n" + pixel(128, 64, 0, 129) + pixel(200, 1, 1, 0));
  REQUIRE(image.width() == 2);
  REQUIRE(image.height() == 1);
  CHECK(image.pixel(0) == std::array<float, 3>{128.5f / 128.0f, 64.5f / 128.0f, 0.5f / 128.0f});
  CHECK(image.pixel(1) == std::array<float, 3>{0.0f, 0.0f, 0.0f});
  CHECK(decoded("#?RGBE\r\nEXPOSURE=2\n# a comment\n\n-Y 1 +X 1\n" + pixel(128, 128, 128, 128)).pixel(0)[0] ==
        128.5f / 256.0f);
}

TEST_CASE("run-length scanlines decode: runs repeat a byte, counts up to 128 are literals") {
  const std::string scanline = std::string("\x02\x02\x00\x08", 4) + char(128 + 8) + char(128) +  // red: run of 8
                               char(8) + "\x01\x02\x03\x04\x05\x06\x07\x08" +                     // green: literals
                               char(3) + "\x09\x0a\x0b" + char(128 + 5) + char(0) +                // blue: both
                               char(128 + 8) + char(130);                                          // exponent
  const RgbImage image = decoded(header + "-Y 2 +X 8\n" + scanline + scanline);
  REQUIRE(image.pixels() == 16);
  CHECK(image.pixel(3, 1)[0] == 128.5f / 64.0f);
  CHECK(image.pixel(3, 1)[1] == 4.5f / 64.0f);
  CHECK(image.pixel(1, 0)[2] == 10.5f / 64.0f);
  CHECK(image.pixel(7, 0)[2] == 0.5f / 64.0f);
}

TEST_CASE("encoded pictures decode to within the 8-bit mantissa and re-encode to the same bytes") {
  for (const auto scanlines : {HdrScanlines::run_length, HdrScanlines::flat}) {
    for (const std::size_t width : {std::size_t(5), std::size_t(37), std::size_t(300)}) {
      const RgbImage original = gradient(width, 9);
      const Bytes bytes = encode_radiance_hdr(original, scanlines);
      const RgbImage back = decode_radiance_hdr(bytes, "round.hdr");
      REQUIRE(back.width() == width);
      REQUIRE(back.height() == 9);
      for (std::size_t p = 0; p < back.pixels(); ++p) {
        const auto a = original.pixel(p), b = back.pixel(p);
        const float largest = std::max({a[0], a[1], a[2]});
        for (std::size_t k = 0; k < 3; ++k) REQUIRE_THAT(b[k], WithinAbs(a[k], largest / 256.0f));
      }
      CHECK(encode_radiance_hdr(back, scanlines) == bytes);
    }
  }
  const Bytes runs = encode_radiance_hdr(RgbImage(300, 4, {1.0f, 1.0f, 1.0f}));
  const Bytes flat = encode_radiance_hdr(RgbImage(300, 4, {1.0f, 1.0f, 1.0f}), HdrScanlines::flat);
  CHECK(runs.size() < flat.size() / 10);
  CHECK(text_of(runs).starts_with("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 300\n"));
  CHECK_THROWS_AS(encode_radiance_hdr(RgbImage(2, 2, {-1.0f, 0.0f, 0.0f})), std::invalid_argument);
  CHECK_THROWS_AS(encode_radiance_hdr(RgbImage(2, 2, {INFINITY, 0.0f, 0.0f})), std::invalid_argument);
  CHECK_THROWS_AS(encode_radiance_hdr(RgbImage()), std::invalid_argument);
}

TEST_CASE("malformed headers are refused with the file and the byte offset") {
  CHECK_THAT(refusal("P6\n1 1\n255\nabc"), ContainsSubstring("is not a Radiance HDR picture") &&
                                             ContainsSubstring("at byte 0"));
  CHECK_THAT(refusal(""), ContainsSubstring("is not a Radiance HDR picture"));
  CHECK_THAT(refusal("#?RADIANCEX\n\n-Y 1 +X 1\n"), ContainsSubstring("is not a Radiance HDR picture"));
  CHECK_THAT(refusal("#?RADIANCE"), ContainsSubstring("the header ends without a resolution line at byte 10"));
  CHECK_THAT(refusal("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n"), ContainsSubstring("without a resolution line at byte 34"));
  CHECK_THAT(refusal("#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\n"),
             ContainsSubstring("the pixel format 'FORMAT=32-bit_rle_xyze' is not supported") &&
                 ContainsSubstring("at byte 11"));
  CHECK_THAT(refusal(header + "-Y 1 +X 1"), ContainsSubstring("without a resolution line at byte 44"));
  CHECK_THAT(refusal(header + "-Y one +X 1\n"),
             ContainsSubstring("the resolution line '-Y one +X 1' is not understood") && ContainsSubstring("at byte 35"));
  CHECK_THAT(refusal(header + "-Y 1 -Y 1\n"), ContainsSubstring("is not understood"));
  CHECK_THAT(refusal(header + "-Y 1 +X 1 extra\n"), ContainsSubstring("is not understood"));
  CHECK_THAT(refusal(header + "-Y 1 +X -1\n"), ContainsSubstring("is not understood"));
  CHECK_THAT(refusal(header + "+Y 1 +X 1\n" + pixel(1, 1, 1, 1)),
             ContainsSubstring("the orientation '+Y 1 +X 1' is not supported (only -Y HEIGHT +X WIDTH") &&
                 ContainsSubstring("at byte 35"));
  CHECK_THAT(refusal(header + "+X 1 -Y 1\n" + pixel(1, 1, 1, 1)), ContainsSubstring("is not supported"));
  CHECK_THAT(refusal(header + "-Y 1 -X 1\n" + pixel(1, 1, 1, 1)), ContainsSubstring("is not supported"));
  CHECK_THAT(refusal(header + "-Y 0 +X 1\n"), ContainsSubstring("has no pixels"));
}

TEST_CASE("hostile dimensions are refused before anything is allocated") {
  CHECK_THAT(refusal(header + "-Y 100000 +X 100000\n"),
             ContainsSubstring("100000 x 100000 texels is larger than the 67108864 read at most at byte 35"));
  CHECK_THAT(refusal(header + "-Y 1234567890 +X 1\n"), ContainsSubstring("the dimension 1234567890... is too large"));
  CHECK_THAT(refusal(header + "-Y 8192 +X 8192\n" + std::string(1000, '\x02')),
             ContainsSubstring("the data ends before the 8192 scanlines of 8192 pixels") &&
                 ContainsSubstring("at byte 1051"));
}

TEST_CASE("truncated and inconsistent scanlines are refused with the offset") {
  const std::string res = header + "-Y 2 +X 8\n";  // scanlines start at byte 45
  const std::string start = std::string("\x02\x02\x00\x08", 4);
  const std::string runs = start + char(128 + 8) + 'a' + char(128 + 8) + 'b' + char(128 + 8) + 'c' + char(128 + 8);
  CHECK(decoded(res + runs + 'd' + runs + 'd').pixels() == 16);
  CHECK_THAT(refusal(res + std::string(32, '\x05') + std::string(30, '\x05')),
             ContainsSubstring("the data ends inside scanline 1 at byte 107"));
  CHECK_THAT(refusal(res + std::string(32, '\x01') + runs), ContainsSubstring("the data ends inside scanline 1 at byte 88"));
  CHECK_THAT(refusal(res + runs + 'd' + runs),
             ContainsSubstring("the data ends before the 2 scanlines of 8 pixels the resolution line declares at byte 68"));
  CHECK_THAT(refusal(res + std::string("\x02\x02\x00\x09", 4) + std::string(60, '\x00')),
             ContainsSubstring("scanline 0 declares 9 pixels; the picture is 8 wide at byte 45"));
  CHECK_THAT(refusal(res + start + '\0' + std::string(60, '\x01')),
             ContainsSubstring("scanline 0 has a run of length 0 at byte 49"));
  CHECK_THAT(refusal(res + start + char(128 + 9) + std::string(60, '\x01')),
             ContainsSubstring("a run of scanline 0 goes past the end of the scanline at byte 49"));
  CHECK_THAT(refusal(res + start + char(4) + "abcd" + char(5) + std::string(60, 'x')),
             ContainsSubstring("a run of scanline 0 goes past the end of the scanline at byte 54"));
}

TEST_CASE("damaged pictures give a picture or an InputError, never anything else") {
  const Bytes valid = encode_radiance_hdr(gradient(40, 6));
  for (std::size_t length = 0; length < valid.size(); ++length) {
    const Bytes cut(valid.begin(), valid.begin() + std::ptrdiff_t(length));
    CHECK_THROWS_AS(decode_radiance_hdr(cut, "cut.hdr"), pbrfit::InputError);
  }
  pbrfit::RandomStream random(3, 0);
  for (int trial = 0; trial < 2000; ++trial) {
    Bytes damaged = valid;
    for (int k = 0; k < 3; ++k) damaged[random.below(damaged.size())] = std::byte(random.below(256));
    try {
      const RgbImage image = decode_radiance_hdr(damaged, "damaged.hdr");
      CHECK(image.pixels() <= max_hdr_texels);
    } catch (const pbrfit::InputError&) {
    }
  }
}
