#pragma once
// Any BRDF evaluated on the MERL grid (merl_grid.hpp) at each cell's centre direction pair, as a table
// that is used exactly like a measured one (merl_table.hpp).
//
// Contract: cell c of channel k holds brdf(wi, wo)[k] for the centre of cell c (from_half_diff); a value
// that is negative or not finite is stored as missing (NaN), as MERL does with unmeasured cells.
#include <array>
#include <functional>

#include "pbrfit/brdf/merl_table.hpp"
#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::brdf {

using DirectionalRgb = std::function<std::array<double, 3>(const Vector3& wi, const Vector3& wo)>;

MerlTable tabulate_on_merl_grid(const DirectionalRgb& brdf);

}  // namespace pbrfit::brdf
