#include "pbrfit/ebrdf/footprint_samples.hpp"

#include <algorithm>
#include <numeric>

namespace pbrfit::ebrdf {
namespace {

std::uint64_t component_key(Component c) { return c == Component::specular ? 0 : 1; }

}  // namespace

std::size_t mip_side(std::size_t size, std::size_t level) { return std::max<std::size_t>(1, size >> level); }

std::size_t mip_levels(std::size_t size) {
  std::size_t levels = 0;
  while ((std::size_t(1) << (levels + 1)) <= size) ++levels;
  return levels;
}

FootprintSampler::FootprintSampler(const NormalMap& map, const EbrdfSampling& sampling, const AlbedoCurve& albedo)
    : map_(map), sampling_(sampling), albedo_(albedo) {}

std::vector<std::size_t> FootprintSampler::contributing_texels(const MipTexel& texel) const {
  const std::size_t side = std::min(map_.size(), std::size_t(1) << texel.level);
  std::vector<std::size_t> texels;
  texels.reserve(side * side);
  for (std::size_t dy = 0; dy < side; ++dy)
    for (std::size_t dx = 0; dx < side; ++dx)
      texels.push_back((texel.x * side + dx) + (texel.y * side + dy) * map_.size());
  if (texels.size() <= sampling_.samples) return texels;
  RandomStream shuffle(sampling_.seed, component_key(sampling_.lobe.component),
                       (std::uint64_t(texel.level) << 40) | (texel.y << 20) | texel.x);
  for (std::size_t i = 0; i < sampling_.samples; ++i)
    std::swap(texels[i], texels[i + shuffle.below(texels.size() - i)]);
  texels.resize(sampling_.samples);
  return texels;
}

std::vector<Vector3> FootprintSampler::samples(const std::vector<std::size_t>& contributing,
                                                    std::size_t view) const {
  const std::size_t per_texel = (sampling_.samples + contributing.size() - 1) / contributing.size();
  const Vector3 v = sampling_.views.direction(view);
  std::vector<std::vector<Vector3>> lobes;
  lobes.reserve(contributing.size());
  for (std::size_t t : contributing) {
    RandomStream stream(sampling_.seed, t, (component_key(sampling_.lobe.component) << 32) | view);
    lobes.push_back(sample_base_lobe(sampling_.lobe, map_.normals()[t], v, per_texel, stream));
  }
  const double phi = sampling_.views.phi(view % sampling_.views.n_phi);
  std::vector<Vector3> pooled;
  pooled.reserve(sampling_.samples);
  for (std::size_t round = 0; pooled.size() < sampling_.samples; ++round)
    for (std::size_t t = 0; t < lobes.size() && pooled.size() < sampling_.samples; ++t)
      pooled.push_back(rotate_azimuth_to_zero(lobes[t][round], phi));
  return pooled;
}

double FootprintSampler::amplitude(const MipTexel& texel, std::size_t view) const {
  const std::size_t side = std::min(map_.size(), std::size_t(1) << texel.level);
  const Vector3 v = sampling_.views.direction(view);
  double sum = 0.0;
  for (std::size_t dy = 0; dy < side; ++dy)
    for (std::size_t dx = 0; dx < side; ++dx)
      sum += albedo_.at(v.dot(map_.normals()[(texel.x * side + dx) + (texel.y * side + dy) * map_.size()]));
  return sum / double(side * side);
}

}  // namespace pbrfit::ebrdf
