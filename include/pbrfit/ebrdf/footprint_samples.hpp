#pragma once
// The effective BRDF of a mip texel (Nahmias 2022, section 3.4.1): the base lobes (base_lobe.hpp) of the
// 2^l x 2^l MIP-0 texels of its footprint, pooled into one set of `samples` directions, rotated so that the
// view azimuth is 0 (the LTC table is indexed by the view's azimuth separately).
//  - when the footprint has no more texels than `samples`, every texel contributes in turn (pooled sample
//    k comes from texel k mod T of the T texels), until the set is full;
//  - otherwise `samples` distinct texels are chosen (a partial Fisher-Yates shuffle keyed by (seed,
//    component, level, mip texel), the same for every view) and each contributes one sample;
//  - pooled sample k is drawn from stratified point k of the unit square (base_lobe.hpp), shifted by a
//    random offset keyed by (seed, component, view, footprint): the set covers each lobe evenly rather
//    than by independent draws, so a fit of 128 samples is not limited by their noise (a flat footprint
//    gives back its base LTC);
//  - the amplitude is the mean of the base lobes' amplitudes (albedos) over all the footprint's texels.
//
// Contract: pure functions of (map, settings, level, x, y, view); level 0 is the texel's own lobe.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "pbrfit/ebrdf/base_lobe.hpp"
#include "pbrfit/ebrdf/normal_map.hpp"
#include "pbrfit/ebrdf/view_grid.hpp"

namespace pbrfit::ebrdf {

struct EbrdfSampling {
  BaseLobe lobe;
  ViewGrid views;
  std::size_t samples = 128;
  std::uint64_t seed = 0;
};

struct MipTexel {
  std::size_t level = 1;
  std::size_t x = 0, y = 0;
};

// The side of mip level `level` of a map of side `size` (size >> level, at least 1).
std::size_t mip_side(std::size_t size, std::size_t level);
// The number of levels above MIP 0: log2(size).
std::size_t mip_levels(std::size_t size);

class FootprintSampler {
 public:
  // The map and the base lobe (of sampling.lobe) must outlive the sampler.
  FootprintSampler(const NormalMap& map, const EbrdfSampling& sampling, const BaseLobeLtc& base);

  const EbrdfSampling& sampling() const { return sampling_; }
  // The MIP-0 texels (x + y * size) that contribute to the texel, in pooling order.
  std::vector<std::size_t> contributing_texels(const MipTexel& texel) const;
  // The pooled set of the given contributing texels (from contributing_texels) for one view.
  std::vector<Vector3> samples(const std::vector<std::size_t>& contributing, std::size_t view) const;
  // The random shift of the stratified points of that pooled set (keyed by the footprint and the view).
  std::array<double, 2> shift(const std::vector<std::size_t>& contributing, std::size_t view) const;
  double amplitude(const MipTexel& texel, std::size_t view) const;

 private:
  const NormalMap& map_;
  EbrdfSampling sampling_;
  const BaseLobeLtc& base_;
};

}  // namespace pbrfit::ebrdf
