#pragma once
// The work items of an `ebrdf` job: item 0 writes the MIP-0 normal map; then, component by component
// (in settings order) and level by level (1 .. max_level), the tiles of each mip level in row-major
// order, a tile being at most tile x tile mip texels.
//
// Invariants: item ids are dense, 0 .. count() - 1; find() is the inverse of the enumeration.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "pbrfit/jobs/ebrdf/ebrdf_settings.hpp"

namespace pbrfit::jobs::ebrdf {

struct TileItem {
  std::size_t component = 0;  // index into EbrdfSettings::components
  std::size_t level = 1;
  std::size_t side = 1;       // mip texels per side of the level
  std::size_t x0 = 0, y0 = 0, width = 1, height = 1;  // the tile, in mip texels
};

class TileItems {
 public:
  explicit TileItems(const EbrdfSettings& settings);

  std::uint64_t count() const { return 1 + tiles_.size(); }
  // The tile of an item >= 1.
  const TileItem& find(std::uint64_t item) const { return tiles_.at(item - 1); }

 private:
  std::vector<TileItem> tiles_;
};

}  // namespace pbrfit::jobs::ebrdf
