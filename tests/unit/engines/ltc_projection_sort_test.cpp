// The projection sort kernels (src/ltc/projection_sort.hpp) in every kernel set against std::sort by
// (key, index), and the sliced Wasserstein distance's order as a function of the matrix alone.
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include "kernel_set_scope.hpp"
#include "pbrfit/core/kernel_set.hpp"
#include "pbrfit/ltc/clamped_cosine.hpp"
#include "pbrfit/ltc/point_sets.hpp"
#include "pbrfit/ltc/sliced_wasserstein.hpp"
#include "projection_sort.hpp"

using pbrfit::KernelSet;
using pbrfit::Matrix3;
using pbrfit::Vector3;

namespace {

// The reference: indices by (key, index), and the values in that order.
void reference_sort(const std::vector<double>& keys, const std::vector<double>& values, std::vector<double>& sorted,
                    std::vector<std::uint32_t>& order) {
  order.resize(keys.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return keys[a] < keys[b] || (keys[a] == keys[b] && a < b);
  });
  sorted.resize(keys.size());
  for (std::size_t r = 0; r < keys.size(); ++r) sorted[r] = values[order[r]];
}

// Keys with ties, signed zeros and infinities among ordinary values; values differ from keys where a key is
// +inf, as the caller's NaN mapping makes them.
std::vector<double> keys_of(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_int_distribution<int> pick(0, 9);
  std::normal_distribution<double> normal;
  std::vector<double> keys(n);
  for (double& key : keys) {
    switch (pick(random)) {
      case 0: key = 0.0; break;
      case 1: key = -0.0; break;
      case 2: key = 0.25; break;  // a tie with every other 0.25
      case 3: key = std::numeric_limits<double>::infinity(); break;
      case 4: key = -std::numeric_limits<double>::infinity(); break;
      default: key = normal(random);
    }
  }
  return keys;
}

}  // namespace

TEST_CASE("The projection sort orders by (key, index) in every kernel set, any length", "[ltc][kernels]") {
  for (const KernelSet set : pbrfit::kernel_sets_available()) {
    const auto sort = pbrfit::ltc::detail::projection_sort(set);
    for (const std::size_t n : {1u, 2u, 3u, 7u, 8u, 9u, 31u, 127u, 128u, 129u, 300u}) {
      for (const std::uint64_t seed : {1u, 2u, 3u}) {
        const std::vector<double> keys = keys_of(n, seed);
        std::vector<double> values = keys;
        for (double& v : values)
          if (v == std::numeric_limits<double>::infinity()) v = std::numeric_limits<double>::quiet_NaN();
        std::vector<double> expected_sorted, sorted(n, -1.0);
        std::vector<std::uint32_t> expected_order, order(n, 0xffffffffu);
        reference_sort(keys, values, expected_sorted, expected_order);
        sort.rank(keys.data(), values.data(), n, sorted.data(), order.data());
        CAPTURE(pbrfit::kernel_set_name(set), n, seed);
        CHECK(order == expected_order);
        CHECK(std::memcmp(sorted.data(), expected_sorted.data(), n * sizeof(double)) == 0);
      }
    }
  }
}

TEST_CASE("Sliced Wasserstein pairs tied projections by index, whatever the previous matrix", "[ltc]") {
  // Base samples in mirrored pairs (x, y, z) and (-x, y, z); m keeps the mirror, so on the axes without an x
  // component each pair's projections tie exactly. The targets sit just above and just below each pair, so
  // which sample of a pair takes which target changes the gradient. Before samples were ordered by
  // (projection, index), an object that had seen a matrix breaking the mirror kept that matrix's order of
  // the pairs, and its gradient at m differed from a fresh object's.
  std::vector<Vector3> base;
  for (const Vector3& s : pbrfit::ltc::cosine_samples(64)) base.insert(base.end(), {s, Vector3(-s.x(), s.y(), s.z())});
  Matrix3 m;
  m << 1.0, 0.0, 0.0, 0.0, 0.7, 0.2, 0.0, 0.1, 1.0;
  std::vector<Vector3> targets(base.size());
  for (std::size_t k = 0; k < targets.size(); ++k)
    targets[k] = ((m * base[k]).normalized() + Vector3(0.0, 0.0, k % 2 ? -1e-3 : 1e-3)).normalized();
  std::vector<Vector3> axes = {Vector3(0.0, 0.6, 0.8), Vector3(0.0, -0.8, 0.6), Vector3(0.0, 0.0, 1.0),
                               Vector3(0.0, 1.0, 0.0)};
  for (const Vector3& a : pbrfit::ltc::axis_directions(4)) axes.push_back(a);
  Matrix3 far;
  far << 0.2, -1.0, 0.4, 1.0, 0.3, 0.0, -0.5, 0.2, 0.6;
  for (const KernelSet set : pbrfit::kernel_sets_available()) {
    const kernel_test::KernelSetScope scope(set);
    pbrfit::ltc::SlicedWasserstein fresh(targets, base, axes);
    Matrix3 expected;
    const double expected_value = fresh.gradient(m, expected);
    const double expected_distance = fresh.distance(m);
    // Small steps away and back (insertion sorts) and far matrices (the vector ranking), then m again.
    for (const Matrix3& detour : {Matrix3(1.001 * m), Matrix3(m + 0.01 * far), Matrix3(m + 0.3 * far), far}) {
      pbrfit::ltc::SlicedWasserstein used(targets, base, axes);
      Matrix3 ignored, gradient;
      for (int r = 0; r < 3; ++r) {
        used.gradient(detour, ignored);
        used.gradient(m.transpose(), ignored);
      }
      const double value = used.gradient(m, gradient);
      CAPTURE(pbrfit::kernel_set_name(set), detour);
      CHECK(value == expected_value);
      CHECK(std::memcmp(gradient.data(), expected.data(), sizeof expected) == 0);
      CHECK(used.distance(m) == expected_distance);
    }
  }
}
