#pragma once
// Directional moments of the target lobe rho (ggx_target.hpp), the per-cell constants of an LTC table:
//   albedo  = integral of rho(l) dl                      (the LTC amplitude, "norm", published ltc_2.x)
//   fresnel = integral of rho(l) (1 - v . h)^5 dl        (the Schlick term, published ltc_2.y)
//   average_direction = normalize(integral of rho(l) l dl), its y component cleared (0 by symmetry),
// estimated with the target's own sampling over a golden lattice of `points` points: each weight rho / pdf
// = G2 / G1 is smooth where l.z > 0, so the estimates converge quickly and are reproducible.
//
// Invariants: 0 <= fresnel <= albedo <= 1; average_direction is unit with y = 0 and z > 0.
#include <cstddef>

#include "pbrfit/ltc/ggx_target.hpp"
#include "pbrfit/ltc/vector.hpp"

namespace pbrfit::ltc {

struct GgxMoments {
  double albedo = 0.0;
  double fresnel = 0.0;
  Vector3 average_direction = Vector3::UnitZ();
};

GgxMoments measure_moments(const GgxTarget& target, std::size_t points);

}  // namespace pbrfit::ltc
