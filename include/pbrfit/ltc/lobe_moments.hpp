#pragma once
// Directional moments of a lobe rho (brdf/lobe.hpp), the per-cell constants of an LTC table:
//   albedo  = integral of rho(l) dl                      (the LTC amplitude, "norm", published ltc_2.x)
//   fresnel = integral of rho(l) (1 - v . h)^5 dl        (the Schlick term, published ltc_2.y)
//   average_direction = normalize(integral of rho(l) l dl), its y component cleared (0 by symmetry),
// estimated with the lobe's own sampling over a golden lattice of `points` points (for GGX each weight
// rho / pdf = G2 / G1 is smooth where l.z > 0, so the estimates converge quickly); reproducible.
//
// Invariants: 0 <= fresnel <= albedo; average_direction is unit with y = 0 (the normal when rho is 0).
#include <cstddef>

#include "pbrfit/brdf/lobe.hpp"
#include "pbrfit/geometry/vector.hpp"
#include "pbrfit/ltc/lobe_samples.hpp"

namespace pbrfit::ltc {

struct LobeMoments {
  double albedo = 0.0;
  double fresnel = 0.0;
  Vector3 average_direction = Vector3::UnitZ();
};

LobeMoments measure_moments(const brdf::Lobe& lobe, std::size_t points);
// The same from the lobe's samples (sample_lobe(lobe, points)), already drawn.
LobeMoments measure_moments(const brdf::Lobe& lobe, const LobeSamples& samples);

}  // namespace pbrfit::ltc
