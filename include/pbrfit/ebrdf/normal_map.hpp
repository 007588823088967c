#pragma once
// A square, tiling tangent-space normal map: the MIP-0 micro-normals an effective BRDF is built from.
//
// Invariants: size() is a power of two >= 1; every normal is a unit vector with z >= min_normal_z (a normal
// at or below the geometric horizon cannot be shaded; decoding clamps it up); texel (x, y) is x + y * size,
// row y = 0 first; at() wraps coordinates (the map tiles).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::ebrdf {

inline constexpr double min_normal_z = 0.01;

bool is_power_of_two(std::size_t n);

class NormalMap {
 public:
  // Throws std::invalid_argument unless size is a power of two and normals has size * size entries.
  NormalMap(std::size_t size, std::vector<Vector3> normals);

  std::size_t size() const { return size_; }
  const Vector3& at(std::int64_t x, std::int64_t y) const;
  std::span<const Vector3> normals() const { return normals_; }

 private:
  std::size_t size_;
  std::vector<Vector3> normals_;
};

// A unit normal from any vector: normalized, lifted to z >= min_normal_z (a zero or non-finite vector
// becomes the geometric normal).
Vector3 shadable_normal(const Vector3& n);

// The usual 8-bit encoding: each channel c maps to 2 c / 255 - 1 (x right, y along rows, z out); rgb holds
// size * size pixels, R G B adjacent, row-major.
NormalMap decode_normal_map(std::size_t size, std::span<const std::uint8_t> rgb);

}  // namespace pbrfit::ebrdf
