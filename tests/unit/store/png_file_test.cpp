// PNG pictures: 8-bit levels, a valid file (signature, IHDR, pixels read back by stb_image), written
// atomically, failures reported with the reason.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wunused-but-set-variable"
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

#include "pbrfit/core/error.hpp"
#include "pbrfit/store/png_file.hpp"
#include "store_test_paths.hpp"

using namespace pbrfit;
using Catch::Matchers::ContainsSubstring;

namespace {

std::vector<unsigned char> file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::uint32_t big_endian(const std::vector<unsigned char>& b, std::size_t at) {
  return std::uint32_t(b[at]) << 24 | std::uint32_t(b[at + 1]) << 16 | std::uint32_t(b[at + 2]) << 8 | b[at + 3];
}

RgbImage pattern(std::size_t width, std::size_t height) {
  RgbImage image(width, height);
  for (std::size_t p = 0; p < image.pixels(); ++p)
    image.set(p, {float(p % 7) / 6.0f, float(p % 256) / 255.0f, p % 2 ? 1.5f : -0.2f});
  return image;
}

}  // namespace

TEST_CASE("display values become 8-bit levels: clamped, rounded, NaN black") {
  const std::vector<std::uint8_t> levels = store::png_samples(RgbImage(1, 1, {0.5f, 2.0f, -1.0f}));
  CHECK(levels == std::vector<std::uint8_t>{128, 255, 0});
  CHECK(store::png_samples(RgbImage(1, 1, {NAN, 1.0f / 255.0f, 0.998f})) == std::vector<std::uint8_t>{0, 1, 254});
}

TEST_CASE("a PNG file is written atomically with the right signature, header and pixels") {
  const std::string path = temporary_path("sphere.png");
  const RgbImage image = pattern(37, 11);
  store::write_png_file(path, image);
  CHECK_FALSE(std::filesystem::exists(path + ".tmp"));
  const auto bytes = file_bytes(path);
  REQUIRE(bytes.size() > 33);
  CHECK(std::vector<unsigned char>(bytes.begin(), bytes.begin() + 8) ==
        std::vector<unsigned char>{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'});
  CHECK(big_endian(bytes, 8) == 13);
  CHECK(std::string(bytes.begin() + 12, bytes.begin() + 16) == "IHDR");
  CHECK(big_endian(bytes, 16) == 37);
  CHECK(big_endian(bytes, 20) == 11);
  CHECK(bytes[24] == 8);  // bit depth
  CHECK(bytes[25] == 2);  // colour type: RGB
  int width = 0, height = 0, channels = 0;
  unsigned char* pixels = stbi_load_from_memory(bytes.data(), int(bytes.size()), &width, &height, &channels, 3);
  REQUIRE(pixels != nullptr);
  const std::vector<std::uint8_t> read(pixels, pixels + 3 * 37 * 11);
  stbi_image_free(pixels);
  CHECK(width == 37);
  CHECK(height == 11);
  CHECK(read == store::png_samples(image));
}

TEST_CASE("a PNG that cannot be written or encoded is refused with the reason") {
  const std::string path = temporary_path("no-such-directory/sphere.png");
  try {
    store::write_png_file(path, pattern(4, 4));
    FAIL("written");
  } catch (const RunError& e) {
    CHECK_THAT(e.what(), ContainsSubstring("No such file or directory"));
  }
  CHECK_THROWS_AS(store::encode_png(RgbImage()), RunError);
}

TEST_CASE("renders side by side make one picture") {
  const std::vector<RgbImage> images = {pattern(8, 8), pattern(8, 8), pattern(5, 3)};
  const std::string path = temporary_path("row.png");
  store::write_png_file(path, side_by_side(images, 4, {1.0f, 1.0f, 1.0f}));
  const auto bytes = file_bytes(path);
  CHECK(big_endian(bytes, 16) == 8 + 4 + 8 + 4 + 5);
  CHECK(big_endian(bytes, 20) == 8);
}
