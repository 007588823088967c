#include "pbrfit/jobs/ebrdf/ebrdf_items.hpp"

#include <algorithm>

#include "pbrfit/ebrdf/footprint_samples.hpp"

namespace pbrfit::jobs::ebrdf {

TileItems::TileItems(const EbrdfSettings& settings) {
  for (std::size_t c = 0; c < settings.components.size(); ++c)
    for (std::size_t level = 1; level <= settings.max_level; ++level) {
      const std::size_t side = pbrfit::ebrdf::mip_side(settings.map->size(), level);
      for (std::size_t y0 = 0; y0 < side; y0 += settings.tile)
        for (std::size_t x0 = 0; x0 < side; x0 += settings.tile)
          tiles_.push_back({c, level, side, x0, y0, std::min(settings.tile, side - x0),
                            std::min(settings.tile, side - y0)});
    }
}

}  // namespace pbrfit::jobs::ebrdf
