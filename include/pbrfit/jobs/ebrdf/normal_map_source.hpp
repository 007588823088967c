#pragma once
// The normal map an `ebrdf` job names: a built-in pattern (ebrdf/procedural_normal_maps.hpp, of side
// `size`, seeded by the job's seed) or a PNG / TGA file (store/image_file.hpp), square with a power-of-two
// side of at most max_normal_map_side. Problems are InputErrors at the key (a bad file: "'normal_map'
// names PATH: REASON").
#include <cstdint>
#include <memory>
#include <string>

#include "pbrfit/ebrdf/normal_map.hpp"
#include "pbrfit/spec/schema.hpp"

namespace pbrfit::jobs::ebrdf {

inline constexpr std::size_t max_normal_map_side = 512;

struct LoadedNormalMap {
  std::shared_ptr<const pbrfit::ebrdf::NormalMap> map;
  std::string description;
};

LoadedNormalMap load_normal_map(const spec::Section& section, std::uint64_t seed);

}  // namespace pbrfit::jobs::ebrdf
