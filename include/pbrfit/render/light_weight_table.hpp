#pragma once
// The precomputed table of genBRDF's similarity metric (Brady et al. 2014, section 3.5): the sphere
// render with the BRDF replaced by 1, each light sample's weight (sphere_samples.hpp) added to the MERL
// cell (brdf/merl_grid.hpp) of its (wi, wo) instead of to its pixel, per channel. T[cell] is then the
// light the cell would contribute to the image per unit BRDF value.
//
// A table is built from stored samples, or straight from the sampling loop for a pixel range (in double
// precision, storing nothing, so a render of any size fits in the table's 35 MB); tables of disjoint
// ranges add up to the table of their union, so callers may build ranges on separate threads.
//
// Invariants: values() holds 3 x merl_cells entries, channel-major, each finite and >= 0; total(c) is the
// sum of channel c, equal to the sum of that channel over the unit-BRDF render's pixels (up to rounding);
// the table is a pure function of its samples (accumulated in sample order, tables added in the order
// the caller adds them).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "pbrfit/brdf/merl_grid.hpp"
#include "pbrfit/render/rgb.hpp"
#include "pbrfit/render/sphere_samples.hpp"

namespace pbrfit::render {

class LightWeightTable {
 public:
  LightWeightTable();  // no samples: all zero
  explicit LightWeightTable(const SphereSamples& samples);
  LightWeightTable(const EnvironmentMap& environment, const SphereView& view, std::size_t samples_per_pixel,
                   PixelRange range);
  LightWeightTable& operator+=(const LightWeightTable& other);

  double weight(std::size_t channel, std::size_t cell) const { return values_[channel * brdf::merl_cells + cell]; }
  const std::vector<double>& values() const { return values_; }
  Rgb total() const { return total_; }
  // Cells with weight > 0 in some channel.
  std::size_t lit_cells() const;

 private:
  void add(std::uint32_t cell, const Rgb& weight);
  std::vector<double> values_;
  Rgb total_ = {0.0, 0.0, 0.0};
};

}  // namespace pbrfit::render
