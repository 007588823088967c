#pragma once
// A floating-point RGB image: the value type renders, environment maps and picture files share.
//
// Invariants: values() holds 3 x width x height floats, row-major from the top row, each pixel's red,
// green and blue adjacent; pixel index = row * width + column; a default image is 0 x 0. Nothing is
// clamped: linear radiance and display values alike.
#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace pbrfit {

class RgbImage {
 public:
  RgbImage() = default;
  // Every pixel `fill`.
  RgbImage(std::size_t width, std::size_t height, std::array<float, 3> fill = {0.0f, 0.0f, 0.0f});

  std::size_t width() const { return width_; }
  std::size_t height() const { return height_; }
  std::size_t pixels() const { return width_ * height_; }

  std::array<float, 3> pixel(std::size_t index) const {
    return {values_[3 * index], values_[3 * index + 1], values_[3 * index + 2]};
  }
  std::array<float, 3> pixel(std::size_t column, std::size_t row) const { return pixel(row * width_ + column); }
  void set(std::size_t index, std::array<float, 3> rgb);
  void set(std::size_t column, std::size_t row, std::array<float, 3> rgb) { set(row * width_ + column, rgb); }

  std::span<const float> values() const { return values_; }
  std::span<float> values() { return values_; }

 private:
  std::size_t width_ = 0, height_ = 0;
  std::vector<float> values_;
};

// The images in one row, left to right, `gap` pixels apart, top-aligned; the row is as high as the
// highest image and `background` wherever no image is.
RgbImage side_by_side(std::span<const RgbImage> images, std::size_t gap,
                      std::array<float, 3> background = {0.0f, 0.0f, 0.0f});

}  // namespace pbrfit
