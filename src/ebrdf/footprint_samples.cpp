#include "pbrfit/ebrdf/footprint_samples.hpp"

#include <algorithm>
#include <numeric>

#include "pbrfit/core/random_stream.hpp"

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

FootprintSampler::FootprintSampler(const NormalMap& map, const EbrdfSampling& sampling, const BaseLobeLtc& base)
    : map_(map), sampling_(sampling), base_(base) {}

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
  const Vector3 v = sampling_.views.direction(view);
  std::vector<LtcLookup> lobes;
  std::vector<Frame> frames;
  lobes.reserve(contributing.size());
  frames.reserve(contributing.size());
  for (std::size_t t : contributing) {
    lobes.push_back(base_.at(map_.normals()[t], v));
    frames.push_back(texel_frame(map_.normals()[t], v));
  }
  const std::array<double, 2> offset = shift(contributing, view);
  const double phi = sampling_.views.phi(view % sampling_.views.n_phi);
  std::vector<Vector3> pooled;
  pooled.reserve(sampling_.samples);
  for (std::size_t k = 0; k < sampling_.samples; ++k) {
    const std::size_t t = k % contributing.size();
    const auto u = stratified_point(k, sampling_.samples, offset);
    pooled.push_back(rotate_azimuth_to_zero(sample_base_lobe(lobes[t], frames[t], u), phi));
  }
  return pooled;
}

std::array<double, 2> FootprintSampler::shift(const std::vector<std::size_t>& contributing, std::size_t view) const {
  // Keyed by the footprint (its first texel and its size: unique across levels) and the view.
  RandomStream random(sampling_.seed, (component_key(sampling_.lobe.component) << 32) | view,
                      contributing.size() * map_.normals().size() + contributing.front());
  const double x = random.uniform();
  return {x, random.uniform()};
}

double FootprintSampler::amplitude(const MipTexel& texel, std::size_t view) const {
  const std::size_t side = std::min(map_.size(), std::size_t(1) << texel.level);
  const Vector3 v = sampling_.views.direction(view);
  double sum = 0.0;
  for (std::size_t dy = 0; dy < side; ++dy)
    for (std::size_t dx = 0; dx < side; ++dx)
      sum += base_.at(map_.normals()[(texel.x * side + dx) + (texel.y * side + dy) * map_.size()], v).amplitude;
  return sum / double(side * side);
}

}  // namespace pbrfit::ebrdf
