#include <catch2/catch_test_macros.hpp>

#include <cmath>

#include "pbrfit/integrate/halton.hpp"

using namespace pbrfit::integrate;

TEST_CASE("radical inverses mirror the digits of the index", "[halton]") {
  CHECK(radical_inverse(2, 1) == 0.5);
  CHECK(radical_inverse(2, 6) == 0.375);  // 110b -> 0.011b
  CHECK(std::abs(radical_inverse(3, 5) - 7.0 / 9.0) < 1e-15);  // 12_3 -> 0.21_3
}

TEST_CASE("Halton points are stratified in both coordinates", "[halton]") {
  // The first 2^k points hit every interval [j/2^k, (j+1)/2^k) once in x; the first 3^k likewise in y.
  const auto points = halton_points(81);
  std::array<int, 64> x_bins{};
  for (int i = 0; i < 63; ++i) x_bins[static_cast<int>(points[i].at(0) * 64)]++;  // points 1..63 + point 0
  int empty_x = 0;
  for (int count : x_bins) empty_x += count == 0 ? 1 : 0;
  CHECK(empty_x == 1);  // only [0, 1/64), which point 0 (skipped) would fill
  std::array<int, 81> y_bins{};  // points 1..80 are exact multiples of 1/81: round, not truncate
  for (int i = 0; i < 80; ++i) y_bins[std::lround(points[i][1] * 81)]++;
  int empty_y = 0;
  for (int count : y_bins) empty_y += count == 0 ? 1 : 0;
  CHECK(empty_y == 1);
}
