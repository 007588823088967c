// PNG and TGA pictures (normal maps): decoded to 8-bit RGB, and hostile sizes refused from the header,
// before stb_image allocates for the pixels.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers.hpp>

#include <fstream>
#include <string>

#include "pbrfit/core/error.hpp"
#include "pbrfit/core/rgb_image.hpp"
#include "pbrfit/store/image_file.hpp"
#include "pbrfit/store/png_file.hpp"
#include "store_test_paths.hpp"

using namespace pbrfit;

namespace {

std::string refusal(const std::string& path) {
  try {
    store::read_rgb8_image(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

void write_raw(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

std::string big_endian(std::uint32_t v) {
  return {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
}

// A PNG signature and header chunk claiming width x height RGB pixels, with no pixel data after it.
std::string png_header(std::uint32_t width, std::uint32_t height) {
  const std::string ihdr = "IHDR" + big_endian(width) + big_endian(height) + std::string("\x08\x02\x00\x00\x00", 5);
  return std::string("\x89PNG\r\n\x1a\n", 8) + big_endian(13) + ihdr + big_endian(0);
}

}  // namespace

TEST_CASE("a PNG picture reads back as its 8-bit RGB pixels") {
  RgbImage image(3, 2, {0.0f, 0.5f, 1.0f});
  image.set(2, 1, {1.0f, 0.0f, 0.0f});
  const auto path = temporary_path("picture.png");
  store::write_png_file(path, image);
  const auto read = store::read_rgb8_image(path);
  REQUIRE(read.width == 3);
  REQUIRE(read.height == 2);
  CHECK(read.pixels[0] == 0);
  CHECK(read.pixels[1] == 128);
  CHECK(read.pixels[2] == 255);
  CHECK(read.pixels[3 * 5] == 255);
  CHECK(read.pixels[3 * 5 + 1] == 0);
}

TEST_CASE("pictures too large a side are refused from the header, before decoding") {
  const auto path = temporary_path("huge.png");
  const auto side = std::to_string(store::max_image_side);
  write_raw(path, png_header(std::uint32_t(store::max_image_side) + 1, 1));
  CHECK(refusal(path) == path + ": error: picture of " + std::to_string(store::max_image_side + 1) +
                             " x 1 pixels; at most " + side + " per side");
  // stb_image itself refuses more than 2^30 bytes of pixels; below that, pbrfit's limit is what refuses.
  write_raw(path, png_header(16, 1'000'000));
  CHECK(refusal(path) == path + ": error: picture of 16 x 1000000 pixels; at most " + side + " per side");
  // At the limit, the header passes and the missing pixel data is what is refused.
  write_raw(path, png_header(std::uint32_t(store::max_image_side), 1));
  CHECK(refusal(path).starts_with(path + ": error: cannot decode the picture ("));
  write_raw(path, "not a picture at all");
  CHECK(refusal(path).starts_with(path + ": error: not a PNG or TGA picture ("));
}

TEST_CASE("a caller's own size check sees the header's size before any pixel is decoded") {
  const auto path = temporary_path("large-normal-map.png");
  write_raw(path, png_header(4096, 4096));  // the header alone: decoding would fail, and allocate 48 MiB first
  std::size_t seen_width = 0, seen_height = 0;
  const auto too_large = [&](std::size_t width, std::size_t height) {
    seen_width = width, seen_height = height;
    throw InputError({path}, "too large for a normal map");
  };
  CHECK_THROWS_WITH(store::read_rgb8_image(path, too_large), path + ": error: too large for a normal map");
  CHECK(seen_width == 4096);
  CHECK(seen_height == 4096);
  CHECK(refusal(path).starts_with(path + ": error: cannot decode the picture ("));  // without the check
}

TEST_CASE("a PNG chunk claiming more bytes than the file holds is refused before stb_image allocates for it") {
  // The image fuzz target's slow input: a 2 x 2 picture whose IDAT chunk states 1.9 GB (stb_image grew its
  // buffer to that before reading). Any chunk, up to IEND, must lie within the file.
  const auto path = temporary_path("chunk.png");
  const std::string idat = big_endian(0x72000000u) + "IDAT" + std::string("\x78\x9c\x01\x00\x00", 5);
  write_raw(path, png_header(2, 2) + idat);
  CHECK(refusal(path) == path + ": error: PNG chunk at byte 33 claims 1912602624 bytes of data, but only 5 bytes "
                             "follow it (truncated or corrupt picture)");
  // The same chunk stating its true length passes this check (and is then refused by stb_image as corrupt).
  write_raw(path, png_header(2, 2) + big_endian(1) + "IDAT" + "x" + big_endian(0) + big_endian(0) + "IEND" + big_endian(0));
  CHECK(refusal(path).find("PNG chunk") == std::string::npos);
  CHECK(refusal(path) != "(accepted)");
}
