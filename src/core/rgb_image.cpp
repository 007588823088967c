#include "pbrfit/core/rgb_image.hpp"

#include <algorithm>

namespace pbrfit {

RgbImage::RgbImage(std::size_t width, std::size_t height, std::array<float, 3> fill)
    : width_(width), height_(height), values_(3 * width * height) {
  for (std::size_t i = 0; i < pixels(); ++i) set(i, fill);
}

void RgbImage::set(std::size_t index, std::array<float, 3> rgb) {
  std::copy(rgb.begin(), rgb.end(), values_.begin() + std::ptrdiff_t(3 * index));
}

RgbImage side_by_side(std::span<const RgbImage> images, std::size_t gap, std::array<float, 3> background) {
  std::size_t width = 0, height = 0;
  for (const RgbImage& image : images) {
    width += image.width();
    height = std::max(height, image.height());
  }
  if (!images.empty()) width += gap * (images.size() - 1);
  RgbImage row(width, height, background);
  std::size_t left = 0;
  for (const RgbImage& image : images) {
    for (std::size_t y = 0; y < image.height(); ++y)
      for (std::size_t x = 0; x < image.width(); ++x) row.set(left + x, y, image.pixel(x, y));
    left += image.width() + gap;
  }
  return row;
}

}  // namespace pbrfit
