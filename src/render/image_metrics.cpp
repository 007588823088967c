#include "pbrfit/render/image_metrics.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "pbrfit/render/display_transform.hpp"
#include "pbrfit/render/rgb.hpp"

namespace pbrfit::render {
namespace {

constexpr int window_radius = 5;  // 11 taps
constexpr double window_sigma = 1.5;
constexpr double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;

// One value per pixel, row-major.
struct Plane {
  std::size_t width = 0, height = 0;
  std::vector<double> values;
};

void check_pair(const RgbImage& a, const RgbImage& b, std::span<const std::uint8_t> mask) {
  if (a.width() != b.width() || a.height() != b.height())
    throw std::invalid_argument("images of different sizes cannot be compared");
  if (mask.size() != a.pixels()) throw std::invalid_argument("the mask must have one entry per pixel");
  for (std::uint8_t m : mask)
    if (m != 0) return;
  throw std::invalid_argument("the mask marks no pixel");
}

std::array<double, 2 * window_radius + 1> gaussian_taps() {
  std::array<double, 2 * window_radius + 1> taps;
  double sum = 0.0;
  for (int i = -window_radius; i <= window_radius; ++i)
    sum += taps[i + window_radius] = std::exp(-double(i * i) / (2.0 * window_sigma * window_sigma));
  for (double& t : taps) t /= sum;
  return taps;
}

Plane luminance_plane(const RgbImage& image) {
  Plane plane{image.width(), image.height(), std::vector<double>(image.pixels())};
  for (std::size_t p = 0; p < image.pixels(); ++p) plane.values[p] = luminance(to_rgb(image.pixel(p)));
  return plane;
}

Plane product(const Plane& a, const Plane& b) {
  Plane out = a;
  for (std::size_t p = 0; p < out.values.size(); ++p) out.values[p] *= b.values[p];
  return out;
}

// The Gaussian-weighted mean around every pixel along one axis (step 1: rows, step width: columns),
// black outside the image.
Plane blurred_along(const Plane& in, bool vertical) {
  static const auto taps = gaussian_taps();
  Plane out{in.width, in.height, std::vector<double>(in.values.size(), 0.0)};
  const long extent = long(vertical ? in.height : in.width);
  for (std::size_t y = 0; y < in.height; ++y)
    for (std::size_t x = 0; x < in.width; ++x) {
      const long at = long(vertical ? y : x);
      double sum = 0.0;
      for (int i = -window_radius; i <= window_radius; ++i) {
        const long q = at + i;
        if (q < 0 || q >= extent) continue;
        sum += taps[i + window_radius] * in.values[vertical ? std::size_t(q) * in.width + x : y * in.width + std::size_t(q)];
      }
      out.values[y * in.width + x] = sum;
    }
  return out;
}

Plane blurred(const Plane& in) { return blurred_along(blurred_along(in, false), true); }

}  // namespace

double rgb_rms_error(const RgbImage& a, const RgbImage& b, std::span<const std::uint8_t> mask) {
  check_pair(a, b, mask);
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t p = 0; p < a.pixels(); ++p) {
    if (mask[p] == 0) continue;
    for (std::size_t k = 0; k < 3; ++k) {
      const double d = double(a.pixel(p)[k]) - double(b.pixel(p)[k]);
      sum += d * d;
    }
    count += 3;
  }
  return std::sqrt(sum / double(count));
}

double ssim(const RgbImage& a, const RgbImage& b, std::span<const std::uint8_t> mask) {
  check_pair(a, b, mask);
  const Plane x = luminance_plane(a), y = luminance_plane(b);
  const Plane mx = blurred(x), my = blurred(y);
  const Plane sxx = blurred(product(x, x)), syy = blurred(product(y, y)), sxy = blurred(product(x, y));
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t p = 0; p < a.pixels(); ++p) {
    if (mask[p] == 0) continue;
    const double ux = mx.values[p], uy = my.values[p];
    const double vx = sxx.values[p] - ux * ux, vy = syy.values[p] - uy * uy, cxy = sxy.values[p] - ux * uy;
    sum += (2.0 * ux * uy + c1) * (2.0 * cxy + c2) / ((ux * ux + uy * uy + c1) * (vx + vy + c2));
    ++count;
  }
  return sum / double(count);
}

ImageComparison compare_renders(const RgbImage& reference, const RgbImage& test, std::span<const std::uint8_t> mask,
                                double exposure) {
  const RgbImage a = display(reference, exposure), b = display(test, exposure);
  return {rgb_rms_error(a, b, mask), 1.0 - ssim(a, b, mask)};
}

}  // namespace pbrfit::render
