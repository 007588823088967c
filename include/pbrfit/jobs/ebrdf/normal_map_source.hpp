#pragma once
// The normal map an `ebrdf` job names: a built-in pattern (ebrdf/procedural_normal_maps.hpp, of side
// `size`, seeded by the job's seed) or a PNG / TGA file (store/image_file.hpp), square with a power-of-two
// side of at most max_normal_map_side.
#include <cstdint>
#include <memory>
#include <string>

#include "pbrfit/ebrdf/normal_map.hpp"

namespace pbrfit::jobs::ebrdf {

inline constexpr std::size_t max_normal_map_side = 512;

struct LoadedNormalMap {
  std::shared_ptr<const pbrfit::ebrdf::NormalMap> map;
  std::string description;
};

bool is_builtin_normal_map(const std::string& name);
// The built-in pattern `name` of side `size` (a power of two).
LoadedNormalMap builtin_normal_map(const std::string& name, std::size_t size, std::uint64_t seed);
// The picture at `path`; InputError naming the file for one that cannot be read or is not such a map.
LoadedNormalMap normal_map_file(const std::string& path);

}  // namespace pbrfit::jobs::ebrdf
