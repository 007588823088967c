#pragma once
// The layout of the published 64 x 64 GGX LTC table (Heitz et al. 2016; 2017 revision of ltc_code,
// fitLTC.cpp) and the order the paper fits it in.
//  - texel (a, t): a = roughness index (the fast texture axis), t = view index; flat index a + t * size;
//  - perceptual roughness r = a / (size - 1), alpha = max(r^2, min_alpha);
//  - x = t / (size - 1) = sqrt(1 - cos theta_v): cos theta_v = cos(min(acos(1 - x^2), max_theta));
//  - ltc_2.w of texel (a, t) is sphere_form_factor_ratio(2 a / (size - 1) - 1, t / (size - 1))
//    (sphere_form_factor.hpp): a lookup table of its own sharing the texture, not a property of the cell;
//  - marching order: roughness from the smooth end (a = size - 1) down to the mirror, and for each roughness
//    the view from normal (t = 0) to grazing; a cell's warm start is the fit of its predecessor, (a, t - 1),
//    or (a + 1, 0) when t = 0; the first cell (size - 1, 0) has none.
// Invariants: size >= 2; every cell appears exactly once in the marching order, after its predecessor.
#include <cstddef>
#include <optional>
#include <vector>

namespace pbrfit::ltc {

struct TableCell {
  int roughness_index = 0;  // a
  int view_index = 0;       // t
};

struct GgxTableLayout {
  int size = 64;
  double min_alpha = 1e-5;
  double max_theta = 1.57;

  std::size_t flat_index(const TableCell& cell) const;
  double roughness(const TableCell& cell) const;
  double alpha(const TableCell& cell) const;
  double sqrt_one_minus_cos(const TableCell& cell) const;
  double cos_theta_view(const TableCell& cell) const;
  double sphere_term(const TableCell& cell) const;  // the published ltc_2.w of this texel
};

struct MarchingStep {
  TableCell cell;
  std::optional<TableCell> predecessor;
};

std::vector<MarchingStep> marching_order(const GgxTableLayout& layout);

}  // namespace pbrfit::ltc
