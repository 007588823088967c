#include "pbrfit/store/png_file.hpp"

#include <algorithm>
#include <cmath>

#include <stb/stb_image_write.h>

#include "pbrfit/core/error.hpp"
#include "pbrfit/store/atomic_file.hpp"

namespace pbrfit::store {
namespace {

constexpr std::size_t largest_side = std::size_t(1) << 30;

std::uint8_t level(float v) { return std::isnan(v) ? 0 : std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

void append(void* context, void* data, int size) {
  auto* out = static_cast<Bytes*>(context);
  const auto* bytes = static_cast<const std::byte*>(data);
  out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

std::vector<std::uint8_t> png_samples(const RgbImage& display) {
  std::vector<std::uint8_t> samples(display.values().size());
  std::transform(display.values().begin(), display.values().end(), samples.begin(), level);
  return samples;
}

Bytes encode_png(const RgbImage& display) {
  if (display.pixels() == 0) throw RunError("a PNG picture needs at least one pixel");
  if (display.width() >= largest_side || display.height() >= largest_side || display.width() * 3 >= largest_side)
    throw RunError("a picture of " + std::to_string(display.width()) + " x " + std::to_string(display.height()) +
                   " pixels is too large for PNG encoding");
  const std::vector<std::uint8_t> samples = png_samples(display);
  Bytes out;
  const int width = int(display.width()), height = int(display.height());
  if (stbi_write_png_to_func(append, &out, width, height, 3, samples.data(), 3 * width) == 0)
    throw RunError("the PNG encoder failed on a picture of " + std::to_string(width) + " x " + std::to_string(height));
  return out;
}

void write_png_file(const std::string& path, const RgbImage& display) {
  replace_file_atomically(path, encode_png(display));
}

}  // namespace pbrfit::store
