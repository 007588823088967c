#include "pbrfit/ebrdf/normal_map.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace pbrfit::ebrdf {

bool is_power_of_two(std::size_t n) { return n > 0 && (n & (n - 1)) == 0; }

NormalMap::NormalMap(std::size_t size, std::vector<Vector3> normals) : size_(size), normals_(std::move(normals)) {
  if (!is_power_of_two(size) || normals_.size() != size * size)
    throw std::invalid_argument("ebrdf: a normal map is square with a power-of-two side and one normal per texel");
  for (auto& n : normals_) n = shadable_normal(n);
}

const Vector3& NormalMap::at(std::int64_t x, std::int64_t y) const {
  const auto side = static_cast<std::int64_t>(size_);
  const auto wrap = [side](std::int64_t c) { return static_cast<std::size_t>(((c % side) + side) % side); };
  return normals_[wrap(x) + wrap(y) * size_];
}

Vector3 shadable_normal(const Vector3& n) {
  const double length = n.norm();
  if (!std::isfinite(length) || length == 0.0) return Vector3::UnitZ();
  Vector3 unit = n / length;
  if (unit.z() >= min_normal_z) return unit;
  const double tangential = std::hypot(unit.x(), unit.y());
  if (tangential == 0.0) return Vector3::UnitZ();
  const double scale = std::sqrt(1.0 - min_normal_z * min_normal_z) / tangential;
  return {unit.x() * scale, unit.y() * scale, min_normal_z};
}

NormalMap decode_normal_map(std::size_t size, std::span<const std::uint8_t> rgb) {
  if (rgb.size() != 3 * size * size) throw std::invalid_argument("ebrdf: normal map pixels do not match its size");
  std::vector<Vector3> normals(size * size);
  const auto channel = [](std::uint8_t c) { return 2.0 * c / 255.0 - 1.0; };
  for (std::size_t i = 0; i < normals.size(); ++i)
    normals[i] = {channel(rgb[3 * i]), channel(rgb[3 * i + 1]), channel(rgb[3 * i + 2])};
  return NormalMap(size, std::move(normals));
}

}  // namespace pbrfit::ebrdf
