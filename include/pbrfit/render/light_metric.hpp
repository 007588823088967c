#pragma once
// genBRDF's precomputed similarity metric (Brady et al. 2014, equation 4) over the kept cells of a pruned
// light weight table: per channel
//   S'(measured, candidate) = sum over kept cells of (T measured - T candidate)^2
//                           = sum of T^2 (measured - candidate)^2,
// with both BRDFs given as per-kept-cell values, channel-major (3 x size(), in the table's kept order).
//
// Invariants: a cell whose measured value is NaN (missing) is skipped; a NaN candidate value is not (it
// makes the channel's sum NaN, so a broken candidate never looks good); the sums are accumulated in a
// fixed order, so results are deterministic; spans of the wrong length throw std::invalid_argument.
#include <span>
#include <vector>

#include "pbrfit/brdf/merl_table.hpp"
#include "pbrfit/render/brdf_function.hpp"
#include "pbrfit/render/pruned_light_table.hpp"
#include "pbrfit/render/rgb.hpp"

namespace pbrfit::render {

Rgb light_metric(const PrunedLightTable& table, std::span<const double> measured, std::span<const double> candidate);

// A tabulated BRDF's values at the kept cells (NaN where it is missing).
std::vector<double> kept_values(const PrunedLightTable& table, const brdf::MerlTable& brdf);
// A BRDF's values at the kept cells' representative direction pairs (representative_pairs).
std::vector<double> kept_values(const PrunedLightTable& table, const BrdfFunction& brdf);

}  // namespace pbrfit::render
