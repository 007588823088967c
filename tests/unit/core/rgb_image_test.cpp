// RGB images: layout, filling, and composing a row of images.
#include <catch2/catch_test_macros.hpp>

#include <array>
#include <vector>

#include "pbrfit/core/rgb_image.hpp"

using pbrfit::RgbImage;

TEST_CASE("an RGB image stores its pixels row-major from the top, channels adjacent") {
  RgbImage image(3, 2, {0.5f, 0.25f, 0.125f});
  CHECK(image.pixels() == 6);
  CHECK(image.values().size() == 18);
  CHECK(image.pixel(2, 1) == std::array<float, 3>{0.5f, 0.25f, 0.125f});
  image.set(1, 1, {1.0f, 2.0f, 3.0f});
  CHECK(image.pixel(4) == std::array<float, 3>{1.0f, 2.0f, 3.0f});
  CHECK(image.values()[12] == 1.0f);
  CHECK(image.values()[14] == 3.0f);
  CHECK(RgbImage().pixels() == 0);
}

TEST_CASE("side by side puts images in one row with a gap, top-aligned on the background") {
  const std::vector<RgbImage> images = {RgbImage(2, 3, {1.0f, 0.0f, 0.0f}), RgbImage(1, 1, {0.0f, 1.0f, 0.0f})};
  const RgbImage row = pbrfit::side_by_side(images, 2, {0.0f, 0.0f, 1.0f});
  CHECK(row.width() == 5);
  CHECK(row.height() == 3);
  CHECK(row.pixel(1, 2) == std::array<float, 3>{1.0f, 0.0f, 0.0f});
  CHECK(row.pixel(2, 0) == std::array<float, 3>{0.0f, 0.0f, 1.0f});
  CHECK(row.pixel(3, 0) == std::array<float, 3>{0.0f, 0.0f, 1.0f});
  CHECK(row.pixel(4, 0) == std::array<float, 3>{0.0f, 1.0f, 0.0f});
  CHECK(row.pixel(4, 1) == std::array<float, 3>{0.0f, 0.0f, 1.0f});
  CHECK(pbrfit::side_by_side({}, 4).pixels() == 0);
}
