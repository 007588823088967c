#pragma once
// The directional albedo E(cos theta) of a base lobe with F = 1, tabulated once and interpolated: the
// amplitude an effective BRDF inherits from its micro-normals (the mean of E over the footprint's texels,
// each at its own view elevation). Specular: the GGX single-scattering albedo (scale + bias of
// brdf/split_sum_dfg, height-correlated Smith), on `points` cosines uniform in [min_view_cosine, 1],
// linearly interpolated; diffuse: 1.
//
// Invariants: at() clamps its argument to [min_view_cosine, 1]; values in [0, 1]; deterministic.
#include <cstddef>
#include <vector>

#include "pbrfit/ebrdf/base_lobe.hpp"

namespace pbrfit::ebrdf {

class AlbedoCurve {
 public:
  explicit AlbedoCurve(const BaseLobe& lobe, std::size_t points = 65);
  double at(double cos_theta) const;

 private:
  std::vector<double> values_;  // empty: the constant 1
};

}  // namespace pbrfit::ebrdf
