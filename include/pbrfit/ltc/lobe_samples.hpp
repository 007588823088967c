#pragma once
// A lobe rho (brdf/lobe.hpp) sampled by its own sampling over a golden lattice (point_sets.hpp): for each
// lattice point (u1, u2), in the lattice's order, the direction lobe.sample(u1, u2) and rho and the lobe's
// density there (Lobe::evaluate_many: vector code where the lobe has it, the scalar values bit for bit).
// The lobe moments (lobe_moments.hpp) and the fit error's target half (fit_error.hpp) are both sums over
// these samples; an LTC cell whose two lattices have the same size samples the lobe once for both.
//
// Invariants: the three vectors have `points` entries each; a pure function of (lobe, points).
#include <cstddef>
#include <vector>

#include "pbrfit/brdf/lobe.hpp"
#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::ltc {

struct LobeSamples {
  std::vector<Vector3> directions;
  std::vector<double> values;  // rho
  std::vector<double> pdfs;    // the lobe's sampling density
};

LobeSamples sample_lobe(const brdf::Lobe& lobe, std::size_t points);

}  // namespace pbrfit::ltc
