#include "pbrfit/render/procedural_environments.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

namespace pbrfit::render {
namespace {


constexpr std::size_t map_width = 256, map_height = 128;
constexpr double degree = std::numbers::pi / 180.0;

// The image whose every texel holds `radiance` of the direction of its centre.
EnvironmentMap painted(const std::function<Rgb(const Vector3&)>& radiance) {
  RgbImage image(map_width, map_height);
  for (std::size_t row = 0; row < map_height; ++row)
    for (std::size_t column = 0; column < map_width; ++column) {
      const Rgb c = radiance(direction_of(texel_centre({column, row}, map_width, map_height)));
      image.set(column, row, {float(c[0]), float(c[1]), float(c[2])});
    }
  return EnvironmentMap(std::move(image));
}

double elevation(const Vector3& d) { return std::asin(std::clamp(d.y(), -1.0, 1.0)); }

// Azimuth distance from `centre` (radians), wrapped into [0, pi].
double azimuth_distance(const Vector3& d, double centre) {
  return std::abs(std::remainder(angles_of(d).phi - centre, 2.0 * std::numbers::pi));
}

Rgb scaled(const Rgb& c, double s) { return {c[0] * s, c[1] * s, c[2] * s}; }

Rgb interior(const Vector3& d) {
  if (d.y() > std::cos(12.0 * degree)) return {40.0, 38.0, 34.0};
  const double e = elevation(d);
  for (double window : {35.0, 160.0, 260.0})
    if (e > 5.0 * degree && e < 35.0 * degree && azimuth_distance(d, window * degree) < 16.0 * degree)
      return {20.0, 22.0, 26.0};
  if (e < 0.0) return scaled({0.55, 0.36, 0.2}, 0.6 - 0.3 * d.y());
  if (e > 50.0 * degree) return {0.62, 0.6, 0.58};
  return scaled({0.5, 0.5, 0.47}, 0.85 + 0.15 * std::cos(4.0 * angles_of(d).phi));
}

Vector3 sun_direction() { return direction_of({(90.0 - 35.0) * degree, 40.0 * degree}); }

Rgb sky(const Vector3& d) {
  const double e = elevation(d);
  if (e < 0.0) return {0.25, 0.2, 0.15};
  const double angle_to_sun = std::acos(std::clamp(d.dot(sun_direction()), -1.0, 1.0));
  if (angle_to_sun < 2.5 * degree) return {3000.0, 2850.0, 2600.0};
  const double t = e / (0.5 * std::numbers::pi);
  const Rgb horizon = {1.2, 1.3, 1.45}, zenith = {0.25, 0.45, 1.0};
  const double halo = 2.0 * std::exp(-angle_to_sun / (8.0 * degree));
  Rgb c;
  for (std::size_t k = 0; k < 3; ++k) c[k] = horizon[k] * (1.0 - t) + zenith[k] * t + halo * horizon[k];
  return c;
}

}  // namespace

EnvironmentMap procedural_interior() { return painted(interior); }
EnvironmentMap procedural_sky() { return painted(sky); }

}  // namespace pbrfit::render
