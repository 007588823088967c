#pragma once
// The precomputed table of genBRDF's similarity metric (Brady et al. 2014, section 3.5): the sphere
// render with the BRDF replaced by 1, each light sample's weight (sphere_samples.hpp) added to the MERL
// cell (brdf/merl_grid.hpp) of its (wi, wo) instead of to its pixel, per channel. T[cell] is then the
// light the cell would contribute to the image per unit BRDF value.
//
// Invariants: values() holds 3 x merl_cells entries, channel-major, each finite and >= 0; total(c) is the
// sum of channel c, equal to the sum of that channel over the unit-BRDF render's pixels (up to rounding);
// the table is a pure function of the samples (accumulated in sample order).
#include <cstddef>
#include <vector>

#include "pbrfit/brdf/merl_grid.hpp"
#include "pbrfit/render/rgb.hpp"
#include "pbrfit/render/sphere_samples.hpp"

namespace pbrfit::render {

class LightWeightTable {
 public:
  explicit LightWeightTable(const SphereSamples& samples);

  double weight(std::size_t channel, std::size_t cell) const { return values_[channel * brdf::merl_cells + cell]; }
  const std::vector<double>& values() const { return values_; }
  Rgb total() const { return total_; }
  // Cells with weight > 0 in some channel.
  std::size_t lit_cells() const;

 private:
  std::vector<double> values_;
  Rgb total_ = {0.0, 0.0, 0.0};
};

}  // namespace pbrfit::render
