#pragma once
// The MERL BRDF grid (Matusik et al. 2003): 90 theta_h x 90 theta_d x 180 phi_d cells of half/difference
// angles (rusinkiewicz.hpp), one value per cell and colour channel, flat index
// phi_d + theta_d * 180 + theta_h * 180 * 90.
//  - theta_h: cell i holds sqrt(theta_h / (pi/2)) in [i/90, (i+1)/90) (finer near the specular peak);
//  - theta_d: cell j holds theta_d / (pi/2) in [j/90, (j+1)/90);
//  - phi_d: reciprocity folds phi_d into [0, pi) (phi_d + pi when negative); cell k holds phi_d / pi in
//    [k/180, (k+1)/180).
// Indices outside are clamped into the grid (theta_h <= 0 maps to 0). A cell's representative angles are
// the centre of its cell in these coordinates.
//
// Invariants: cell_of(centre_of(c)) == c for every cell; cell_count = 1,458,000.
#include <cstddef>

#include "pbrfit/brdf/rusinkiewicz.hpp"

namespace pbrfit::brdf {

inline constexpr std::size_t merl_theta_h = 90, merl_theta_d = 90, merl_phi_d = 180;
inline constexpr std::size_t merl_cells = merl_theta_h * merl_theta_d * merl_phi_d;

struct MerlCell {
  std::size_t theta_h = 0, theta_d = 0, phi_d = 0;
  std::size_t flat() const { return phi_d + merl_phi_d * (theta_d + merl_theta_d * theta_h); }
};

MerlCell merl_cell_of(const HalfDiff& angles);
MerlCell merl_cell_at(std::size_t flat_index);
// The cell's centre: theta_h, theta_d and phi_d (phi_h = 0).
HalfDiff merl_centre_of(const MerlCell& cell);

}  // namespace pbrfit::brdf
