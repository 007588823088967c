#include "pbrfit/brdf/merl_tabulation.hpp"

#include <cmath>
#include <limits>

#include "pbrfit/brdf/rusinkiewicz.hpp"

namespace pbrfit::brdf {

MerlTable tabulate_on_merl_grid(const DirectionalRgb& brdf) {
  MerlTable table;
  for (std::size_t c = 0; c < merl_cells; ++c) {
    const auto pair = from_half_diff(merl_centre_of(merl_cell_at(c)));
    const auto rgb = brdf(pair.wi, pair.wo);
    for (std::size_t k = 0; k < 3; ++k)
      table.set(k, c, std::isfinite(rgb[k]) && rgb[k] >= 0.0 ? rgb[k] : std::numeric_limits<double>::quiet_NaN());
  }
  return table;
}

}  // namespace pbrfit::brdf
