#include "pbrfit/render/environment_map.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace pbrfit::render {
namespace {

double texel_luminance(const RgbImage& image, const Texel& t) { return luminance(to_rgb(image.pixel(t.column, t.row))); }

RgbImage checked(RgbImage image) {
  if (image.pixels() == 0) throw std::invalid_argument("an environment map needs at least one texel");
  for (float v : image.values())
    if (!std::isfinite(v) || v < 0.0f) throw std::invalid_argument("environment radiance must be finite and >= 0");
  return image;
}

// Luminance x solid angle of each texel of `row`.
std::vector<double> column_weights(const RgbImage& image, std::size_t row) {
  std::vector<double> weights(image.width());
  const double solid_angle = texel_solid_angle(row, image.width(), image.height());
  for (std::size_t c = 0; c < image.width(); ++c) weights[c] = texel_luminance(image, {c, row}) * solid_angle;
  return weights;
}

std::vector<PiecewiseConstant> column_distributions(const RgbImage& image) {
  std::vector<PiecewiseConstant> columns;
  columns.reserve(image.height());
  for (std::size_t r = 0; r < image.height(); ++r) columns.emplace_back(column_weights(image, r));
  return columns;
}

std::vector<double> row_weights(const std::vector<PiecewiseConstant>& columns) {
  std::vector<double> weights;
  weights.reserve(columns.size());
  for (const PiecewiseConstant& row : columns) weights.push_back(row.total_weight());
  return weights;
}

}  // namespace

EnvironmentMap::EnvironmentMap(RgbImage radiance)
    : image_(checked(std::move(radiance))), columns_(column_distributions(image_)), rows_(row_weights(columns_)) {
  if (!(rows_.total_weight() > 0.0)) throw std::invalid_argument("an environment map must not be black everywhere");
}

Texel EnvironmentMap::texel_at(const Vector3& direction) const {
  return texel_of(angles_of(direction), image_.width(), image_.height());
}

double EnvironmentMap::texel_pdf(const Texel& texel) const {
  return texel_luminance(image_, texel) / rows_.total_weight();
}

Rgb EnvironmentMap::radiance(const Vector3& direction) const {
  const Texel t = texel_at(direction);
  return to_rgb(image_.pixel(t.column, t.row));
}

double EnvironmentMap::pdf(const Vector3& direction) const { return texel_pdf(texel_at(direction)); }

EnvironmentSample EnvironmentMap::sample(double u1, double u2) const {
  const BinSample row = rows_.sample(u1);
  const BinSample column = columns_[row.bin].sample(u2);
  const double step = std::numbers::pi / double(image_.height());
  const double top = std::cos(double(row.bin) * step), bottom = std::cos(double(row.bin + 1) * step);
  const double cos_theta = top + row.position * (bottom - top);
  const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  const double phi = (double(column.bin) + column.position) * 2.0 * std::numbers::pi / double(image_.width());
  const Texel texel{column.bin, row.bin};
  return {{sin_theta * std::sin(phi), cos_theta, sin_theta * std::cos(phi)},
          to_rgb(image_.pixel(texel.column, texel.row)),
          texel_pdf(texel)};
}

}  // namespace pbrfit::render
