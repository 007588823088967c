#pragma once
// Built-in tiling normal maps, so that demos and tests need no download (the three maps of Nahmias 2022,
// chapter 4, in spirit):
//  - stone: the height of cobbles (Worley cells: F2 - F1 of a periodic point set, rounded) with fractal
//    value-noise detail; large bumps and ridges;
//  - glitter: flat facets, each a Voronoi cell with its own normal tilted up to 35 degrees in a random
//    direction: a high-frequency, sparkling map;
//  - scratches: a flat surface cut by thin V-shaped grooves along random straight lines.
//
// Contract: a pure function of (pattern, size, seed); size a power of two (1..4096); each map tiles
// seamlessly (every periodic construction uses the map's own period).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "pbrfit/ebrdf/normal_map.hpp"

namespace pbrfit::ebrdf {

enum class NormalPattern { stone, glitter, scratches };

const std::vector<std::string>& normal_pattern_names();
NormalPattern normal_pattern_from(const std::string& name);  // throws std::invalid_argument

NormalMap procedural_normal_map(NormalPattern pattern, std::size_t size, std::uint64_t seed);

// Normals of a periodic height field h (size * size, row-major) by central differences, in units where a
// texel is 1 / size of the map's side: n = normalize(-dh/dx, -dh/dy, 1).
NormalMap normals_from_heights(std::size_t size, const std::vector<double>& heights);

}  // namespace pbrfit::ebrdf
