#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <stdexcept>

#include "pbrfit/ebrdf/normal_map.hpp"
#include "pbrfit/ebrdf/procedural_normal_maps.hpp"

using namespace pbrfit::ebrdf;
using pbrfit::Vector3;

TEST_CASE("normal maps decode the 8-bit encoding, wrap, and lift normals above the horizon") {
  const std::vector<std::uint8_t> rgb = {128, 128, 255, 255, 128, 128, 0, 128, 128, 128, 128, 128};
  const NormalMap map = decode_normal_map(2, rgb);
  CHECK((map.at(0, 0) - Vector3(0.0, 0.0, 1.0)).norm() < 0.01);
  CHECK(map.at(1, 0).z() == min_normal_z);  // (1, 0, 0) lies in the horizon
  CHECK(map.at(1, 0).x() > 0.99);
  CHECK(map.at(0, 1).x() < -0.99);
  CHECK(shadable_normal(Vector3::Zero()) == Vector3::UnitZ());
  CHECK(shadable_normal(Vector3(0.0, 0.0, -1.0)) == Vector3::UnitZ());
  CHECK(&map.at(2, -1) == &map.at(0, 1));
  CHECK_THROWS_AS(NormalMap(3, std::vector<Vector3>(9)), std::invalid_argument);
  CHECK_THROWS_AS(decode_normal_map(2, std::vector<std::uint8_t>(11)), std::invalid_argument);
}

TEST_CASE("the built-in normal maps are deterministic, distinct, bumpy and seamless") {
  for (const auto& name : normal_pattern_names()) {
    INFO(name);
    const NormalPattern pattern = normal_pattern_from(name);
    const NormalMap map = procedural_normal_map(pattern, 64, 3);
    const NormalMap again = procedural_normal_map(pattern, 64, 3);
    const NormalMap other = procedural_normal_map(pattern, 64, 4);
    CHECK(std::equal(map.normals().begin(), map.normals().end(), again.normals().begin()));
    CHECK(!std::equal(map.normals().begin(), map.normals().end(), other.normals().begin()));
    double tilted = 0.0, inner_step = 0.0, seam_step = 0.0;
    int bad = 0;
    for (const Vector3& n : map.normals()) {
      bad += std::abs(n.norm() - 1.0) > 1e-12 || n.z() < min_normal_z;
      tilted += n.z() < std::cos(0.1);
    }
    CHECK(bad == 0);
    CHECK(tilted > 0.05 * 64 * 64);  // a map with texture, not a flat plane
    for (int y = 0; y < 64; ++y) {
      inner_step += (map.at(31, y) - map.at(32, y)).norm();
      seam_step += (map.at(63, y) - map.at(64, y)).norm();
    }
    CHECK(seam_step < 3.0 * inner_step + 0.5);  // the seam is no rougher than the inside
  }
  CHECK_THROWS_AS(normal_pattern_from("marble"), std::invalid_argument);
  CHECK_THROWS_AS(procedural_normal_map(NormalPattern::stone, 48, 1), std::invalid_argument);
}

TEST_CASE("normals of a height field tilt against its slope") {
  std::vector<double> heights(16);
  for (int x = 0; x < 4; ++x)
    for (int y = 0; y < 4; ++y) heights[std::size_t(x + 4 * y)] = x == 1 ? 0.25 : 0.0;
  const NormalMap map = normals_from_heights(4, heights);
  CHECK(map.at(0, 0).x() < -0.1);  // uphill towards +x: the normal leans to -x
  CHECK(map.at(2, 0).x() > 0.1);
  CHECK(map.at(1, 0) == Vector3::UnitZ());
}
