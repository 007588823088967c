#include "pbrfit/render/sphere_renderer.hpp"

#include <cmath>

namespace pbrfit::render {
namespace {

// Each pixel of `range`: the sum over its samples of value(sample) x weight.
template <class SampleValue>
void accumulate(const SphereSamples& samples, PixelRange range, RgbImage& image, const SampleValue& value) {
  for (std::size_t p = range.begin; p < range.end; ++p) {
    Rgb sum = {0.0, 0.0, 0.0};
    for (std::size_t s = samples.first(p); s < samples.first(p + 1); ++s) {
      const Rgb f = value(p, s), w = samples.weight(s);
      for (std::size_t k = 0; k < 3; ++k) sum[k] += f[k] * w[k];
    }
    image.set(p, {float(sum[0]), float(sum[1]), float(sum[2])});
  }
}

double measured_or_zero(double v) { return std::isnan(v) ? 0.0 : v; }

}  // namespace

RgbImage blank_render(const SphereSamples& samples) {
  return RgbImage(samples.view().resolution(), samples.view().resolution());
}

void render_pixels(const SphereSamples& samples, const BrdfFunction& brdf, PixelRange range, RgbImage& image) {
  accumulate(samples, range, image,
             [&](std::size_t p, std::size_t s) { return brdf(samples.wi(s), samples.wo(p)); });
}

void render_pixels(const SphereSamples& samples, const brdf::MerlTable& table, PixelRange range, RgbImage& image) {
  accumulate(samples, range, image, [&](std::size_t, std::size_t s) {
    const std::size_t cell = samples.cell(s);
    return Rgb{measured_or_zero(table.value(0, cell)), measured_or_zero(table.value(1, cell)),
               measured_or_zero(table.value(2, cell))};
  });
}

RgbImage render_sphere(const SphereSamples& samples, const BrdfFunction& brdf) {
  RgbImage image = blank_render(samples);
  render_pixels(samples, brdf, samples.view().all_pixels(), image);
  return image;
}

RgbImage render_sphere(const SphereSamples& samples, const brdf::MerlTable& table) {
  RgbImage image = blank_render(samples);
  render_pixels(samples, table, samples.view().all_pixels(), image);
  return image;
}

}  // namespace pbrfit::render
