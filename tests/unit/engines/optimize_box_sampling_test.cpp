#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/optimize/box_sampling.hpp"

using namespace pbrfit::optimize;

TEST_CASE("A Latin hypercube puts one point in every stratum of every free dimension", "[optimize]") {
  const Bounds bounds{{-1.0, 10.0, 5.0}, {3.0, 20.0, 5.0}};  // the last dimension is fixed
  pbrfit::RandomStream random(3, 0);
  const std::size_t count = 16;
  const auto points = latin_hypercube(bounds, count, random);
  REQUIRE(points.size() == count);
  for (std::size_t d = 0; d < 2; ++d) {
    std::vector<int> hits(count, 0);
    for (const auto& point : points) {
      CHECK(contains(bounds, point));
      const double fraction = (point[d] - bounds.lower[d]) / bounds.width(d);
      ++hits[static_cast<std::size_t>(std::floor(fraction * count))];
    }
    CAPTURE(d);
    CHECK(hits == std::vector<int>(count, 1));
  }
  for (const auto& point : points) CHECK(point[2] == 5.0);
  pbrfit::RandomStream same(3, 0);
  CHECK(latin_hypercube(bounds, count, same) == points);
}
