#include "pbrfit/render/sphere_samples.hpp"

#include <array>
#include <numeric>
#include <stdexcept>

#include "pbrfit/brdf/merl_grid.hpp"
#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/integrate/halton.hpp"

namespace pbrfit::render {
namespace {


// The Cranley-Patterson offset of a pixel: two numbers in [0, 1) hashed from its index.
std::array<double, 2> pixel_offset(std::size_t pixel) {
  const std::uint64_t h = mix64(0x5eed5a3b1e5ULL ^ std::uint64_t(pixel));
  return {double(h >> 40) * 0x1.0p-24, double((h >> 16) & 0xffffff) * 0x1.0p-24};
}

double rotated(double u, double offset) {
  const double v = u + offset;
  return v < 1.0 ? v : v - 1.0;
}

void visit_pixel(const EnvironmentMap& environment, const std::vector<std::array<double, 2>>& points,
                 const SphereView& view, std::size_t pixel, const SampleVisitor& visit) {
  const Frame frame = view.local_frame(pixel);
  const Vector3 wo = view.wo_local(pixel);
  const std::array<double, 2> offset = pixel_offset(pixel);
  const double share = 1.0 / double(points.size());
  for (const auto& point : points) {
    const EnvironmentSample light = environment.sample(rotated(point[0], offset[0]), rotated(point[1], offset[1]));
    const Vector3 wi = frame.to_local(light.direction);
    if (!(wi.z() > 0.0)) continue;
    const double scale = wi.z() * share / light.pdf;
    visit(pixel, wi, wo, {light.radiance[0] * scale, light.radiance[1] * scale, light.radiance[2] * scale});
  }
}

}  // namespace

std::uint32_t merl_cell_of_pair(const Vector3& wi, const Vector3& wo) {
  return std::uint32_t(brdf::merl_cell_of(brdf::to_half_diff(wi, wo)).flat());
}

void visit_light_samples(const EnvironmentMap& environment, const SphereView& view, std::size_t samples_per_pixel,
                         PixelRange range, const SampleVisitor& visit) {
  const auto points = integrate::halton_points(samples_per_pixel);
  for (std::size_t p = range.begin; p < range.end; ++p)
    if (view.on_sphere(p)) visit_pixel(environment, points, view, p, visit);
}

SphereSamples::SphereSamples(const EnvironmentMap& environment, const SphereView& view, std::size_t samples_per_pixel)
    : view_(view), samples_per_pixel_(samples_per_pixel), first_(view.pixels() + 1, 0),
      wo_(view.pixels(), Vector3::Zero()) {
  if (samples_per_pixel == 0) throw std::invalid_argument("a sphere render needs at least one sample per pixel");
  for (std::size_t p = 0; p < view.pixels(); ++p)
    if (view.on_sphere(p)) wo_[p] = view.wo_local(p);
  visit_light_samples(environment, view, samples_per_pixel, view.all_pixels(),
                      [&](std::size_t pixel, const Vector3& wi, const Vector3& wo, const Rgb& weight) {
                        ++first_[pixel + 1];
                        for (std::size_t k = 0; k < 3; ++k) {
                          wi_.push_back(float(wi[k]));
                          weight_.push_back(float(weight[k]));
                        }
                        cell_.push_back(merl_cell_of_pair(wi, wo));
                      });
  std::partial_sum(first_.begin(), first_.end(), first_.begin());
}

void SphereSamples::visit(PixelRange range, const SampleVisitor& visit) const {
  for (std::size_t p = range.begin; p < range.end; ++p)
    for (std::size_t s = first_[p]; s < first_[p + 1]; ++s) visit(p, wi(s), wo_[p], weight(s));
}

}  // namespace pbrfit::render
