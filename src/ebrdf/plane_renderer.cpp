#include "pbrfit/ebrdf/plane_renderer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>

#include "pbrfit/ebrdf/base_lobe.hpp"
#include "pbrfit/ebrdf/view_grid.hpp"
#include "pbrfit/ltc/distribution.hpp"
#include "pbrfit/ltc/polygon_integral.hpp"

namespace pbrfit::ebrdf {
namespace {

using Polygon = std::array<Vector3, 4>;

constexpr std::size_t max_samples_per_side = 48;

// The pixel's texture-space footprint in texels: the larger step to the next column or row.
double texels_per_pixel(const PlaneScene& scene, double column, double row, std::size_t map_size) {
  const auto here = scene.plane_hit(column, row);
  const auto right = scene.plane_hit(column + 1.0, row);
  const auto below = scene.plane_hit(column, row + 1.0);
  if (!here || !right || !below) return 1e9;
  const double step = std::max((*right - *here).head<2>().norm(), (*below - *here).head<2>().norm());
  return step * double(map_size);
}

Polygon light_from(const PlaneScene& scene, const Vector3& p) {
  Polygon q;
  for (std::size_t i = 0; i < 4; ++i) q[i] = scene.light[i] - p;
  return q;
}

double ltc_integral(const LtcLookup& lobe, const Polygon& polygon) {
  if (!(lobe.amplitude > 0.0) || std::abs(lobe.matrix.determinant()) < 1e-12) return 0.0;
  return ltc::LtcDistribution(lobe.matrix, lobe.amplitude).integrate_polygon(polygon);
}

// MIP-0 shading of one micro-normal n at p: base GGX LTC in the texel frame, plus Lambert.
double shade_normal(const RenderInputs& in, const Polygon& light, const Vector3& n, const Vector3& view) {
  const Frame frame = texel_frame(n, view);
  Polygon local;
  for (std::size_t i = 0; i < 4; ++i) local[i] = frame.to_local(light[i]);
  const double specular = ltc_integral(in.base_ltc->at(view.dot(n)), local);
  const double diffuse = ltc::clamped_cosine_polygon_integral(local);
  return in.shading.light_radiance * (in.shading.specular * specular + in.shading.diffuse * diffuse);
}

const Vector3& texel_normal(const NormalMap& map, const Vector3& p) {
  const double n = double(map.size());
  return map.at(static_cast<std::int64_t>(std::floor(p.x() * n)), static_cast<std::int64_t>(std::floor(p.y() * n)));
}

double ground_truth(const PlaneScene& scene, const RenderInputs& in, double column, double row, double rho) {
  const std::size_t s = std::clamp<std::size_t>(std::size_t(std::ceil(1.5 * rho)), in.shading.min_samples,
                                                max_samples_per_side);
  double sum = 0.0;
  for (std::size_t j = 0; j < s; ++j)
    for (std::size_t i = 0; i < s; ++i) {
      const auto p = scene.plane_hit(column + (double(i) + 0.5) / double(s), row + (double(j) + 0.5) / double(s));
      if (!p) continue;
      sum += shade_normal(in, light_from(scene, *p), texel_normal(*in.map, *p), (scene.camera - *p).normalized());
    }
  return sum / double(s * s);
}

// Box-filtered mip pyramid of the normals (unnormalized averages); level 0 is the map.
struct NormalPyramid {
  std::vector<std::vector<Vector3>> levels;
  std::size_t size;

  explicit NormalPyramid(const NormalMap& map) : size(map.size()) {
    levels.emplace_back(map.normals().begin(), map.normals().end());
    for (std::size_t side = size / 2; side >= 1; side /= 2) {
      const auto& finer = levels.back();
      std::vector<Vector3> coarser(side * side);
      for (std::size_t y = 0; y < side; ++y)
        for (std::size_t x = 0; x < side; ++x)
          coarser[x + y * side] = 0.25 * (finer[2 * x + 4 * y * side] + finer[2 * x + 1 + 4 * y * side] +
                                          finer[2 * x + (2 * y + 1) * 2 * side] + finer[2 * x + 1 + (2 * y + 1) * 2 * side]);
      levels.push_back(std::move(coarser));
    }
  }

  Vector3 bilinear(std::size_t level, double u, double v) const {
    const std::size_t side = size >> level;
    const double x = u * double(side) - 0.5, y = v * double(side) - 0.5;
    const double fx = std::floor(x), fy = std::floor(y);
    const auto wrap = [side](double k) {
      const auto s = static_cast<std::int64_t>(side);
      return std::size_t(((static_cast<std::int64_t>(k) % s) + s) % s);
    };
    const double tx = x - fx, ty = y - fy;
    const auto& t = levels[level];
    return (1 - ty) * ((1 - tx) * t[wrap(fx) + wrap(fy) * side] + tx * t[wrap(fx + 1) + wrap(fy) * side]) +
           ty * ((1 - tx) * t[wrap(fx) + wrap(fy + 1) * side] + tx * t[wrap(fx + 1) + wrap(fy + 1) * side]);
  }

  Vector3 trilinear(double level, double u, double v) const {
    const double l = std::clamp(level, 0.0, double(levels.size() - 1));
    const auto low = std::min(levels.size() - 1, static_cast<std::size_t>(l));
    const double t = l - double(low);
    Vector3 n = bilinear(low, u, v) * (1 - t);
    if (t > 0.0) n += bilinear(low + 1, u, v) * t;
    return shadable_normal(n);
  }
};

double ours(const PlaneScene& scene, const RenderInputs& in, const Vector3& p, double rho) {
  const Vector3 view = (scene.camera - p).normalized();
  const Polygon light = light_from(scene, p);
  if (rho < 2.0) return shade_normal(in, light, texel_normal(*in.map, p), view);
  const double level = std::log2(rho);
  const double theta = std::acos(std::clamp(view.z(), -1.0, 1.0));
  double phi = std::atan2(view.y(), view.x());
  if (phi < 0.0) phi += 2.0 * std::numbers::pi;
  Polygon rotated;
  for (std::size_t i = 0; i < 4; ++i) rotated[i] = rotate_azimuth_to_zero(light[i], phi);
  const auto component = [&](const LtcMipTables* tables) {
    if (!tables) return 0.0;
    if (in.shading.filtering == TableFiltering::matrices)
      return ltc_integral(tables->lookup(level, p.x(), p.y(), theta, phi), rotated);
    double sum = 0.0;
    for (const auto& texel : tables->texel_lobes(level, p.x(), p.y(), theta, phi))
      sum += texel.weight * ltc_integral(texel.lobe, rotated);
    return sum;
  };
  return in.shading.light_radiance *
         (in.shading.specular * component(in.specular) + in.shading.diffuse * component(in.diffuse));
}

}  // namespace

double centre_texels_per_pixel(const PlaneScene& scene, std::size_t map_size) {
  const double c = 0.5 * double(scene.resolution);
  return texels_per_pixel(scene, c, c, map_size);
}

RgbImage render_plane(const PlaneScene& scene, RenderMethod method, const RenderInputs& in) {
  RgbImage image(scene.resolution, scene.resolution);
  const auto pyramid = method == RenderMethod::naive ? std::make_unique<const NormalPyramid>(*in.map) : nullptr;
  for (std::size_t row = 0; row < scene.resolution; ++row)
    for (std::size_t column = 0; column < scene.resolution; ++column) {
      const double x = double(column) + 0.5, y = double(row) + 0.5;
      const auto p = scene.plane_hit(x, y);
      if (!p) continue;
      const double rho = texels_per_pixel(scene, x, y, in.map->size());
      double value = 0.0;
      if (method == RenderMethod::ground_truth) value = ground_truth(scene, in, double(column), double(row), rho);
      if (method == RenderMethod::ours) value = ours(scene, in, *p, rho);
      if (method == RenderMethod::naive) {
        const Vector3 n = pyramid->trilinear(std::log2(std::max(rho, 1.0)), p->x(), p->y());
        value = shade_normal(in, light_from(scene, *p), n, (scene.camera - *p).normalized());
      }
      const auto v = float(value);
      image.set(column, row, {v, v, v});
    }
  return image;
}

const char* render_method_name(RenderMethod method) {
  switch (method) {
    case RenderMethod::ground_truth: return "ground_truth";
    case RenderMethod::naive: return "naive";
    case RenderMethod::ours: return "ours";
  }
  return "?";
}

}  // namespace pbrfit::ebrdf
