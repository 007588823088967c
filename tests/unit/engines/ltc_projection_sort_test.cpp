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

// The reference order of keys, shuffled within consecutive blocks of `block` places: no inversion is
// further apart than block - 1.
static std::vector<std::uint32_t> near_order(const std::vector<double>& keys, std::size_t block, std::uint64_t seed) {
  std::vector<double> unused;
  std::vector<std::uint32_t> order;
  reference_sort(keys, keys, unused, order);
  std::mt19937_64 random(seed);
  for (std::size_t first = 0; first < order.size(); first += block)
    std::shuffle(order.begin() + std::ptrdiff_t(first),
                 order.begin() + std::ptrdiff_t(std::min(order.size(), first + block)), random);
  return order;
}

TEST_CASE("The projection re-rank gives the order by (key, index) or declines, in every kernel set", "[ltc][kernels]") {
  for (const KernelSet set : pbrfit::kernel_sets_available()) {
    const auto sort = pbrfit::ltc::detail::projection_sort(set);
    for (const std::size_t n : {1u, 2u, 7u, 9u, 31u, 127u, 128u, 129u, 300u}) {
      std::vector<double> scratch(pbrfit::ltc::detail::rerank_scratch(n));
      std::vector<std::uint32_t> order_scratch(n);
      for (const std::uint64_t seed : {1u, 2u, 3u}) {
        std::mt19937_64 random(seed);
        std::normal_distribution<double> normal;
        std::vector<double> distinct(n);
        for (double& key : distinct) key = normal(random);
        std::vector<double> tied = keys_of(n, seed);
        for (double& key : tied)  // no NaN reaches a re-rank; infinities may
          if (std::isnan(key)) key = 0.0;
        for (const bool with_ties : {false, true}) {
          const std::vector<double>& keys = with_ties ? tied : distinct;
          std::vector<double> expected_sorted;
          std::vector<std::uint32_t> expected_order;
          reference_sort(keys, keys, expected_sorted, expected_order);
          for (const std::size_t block : {1u, 2u, 9u, 17u, 33u, 64u, 300u}) {
            const std::vector<std::uint32_t> previous = near_order(keys, block, seed);
            std::vector<std::uint32_t> order = previous;
            std::vector<double> sorted(n, -1.0);
            const bool done = sort.rerank(keys.data(), n, order.data(), sorted.data(), scratch.data(),
                                          order_scratch.data());
            CAPTURE(pbrfit::kernel_set_name(set), n, seed, with_ties, block);
            if (done) {
              CHECK(order == expected_order);
              CHECK(std::memcmp(sorted.data(), expected_sorted.data(), n * sizeof(double)) == 0);
            } else {
              CHECK(order == previous);  // declined: the last order is kept for the full ranking
            }
            // Distinct keys whose inversions are at most 32 places apart always fit a window.
            if (!with_ties && block <= 33) CHECK(done);
          }
        }
      }
    }
  }
}

TEST_CASE("The projection re-rank declines one sample moved further than its widest window", "[ltc][kernels]") {
  for (const KernelSet set : pbrfit::kernel_sets_available()) {
    const auto sort = pbrfit::ltc::detail::projection_sort(set);
    const std::size_t n = 128;
    std::vector<double> keys(n);
    for (std::size_t k = 0; k < n; ++k) keys[k] = double(k);
    std::vector<double> scratch(pbrfit::ltc::detail::rerank_scratch(n)), sorted(n);
    std::vector<std::uint32_t> order_scratch(n);
    for (const std::size_t distance : {1u, 8u, 9u, 16u, 17u, 32u, 33u, 100u}) {
      // The identity with the sample of rank 10 moved `distance` places later.
      std::vector<std::uint32_t> order(n);
      std::iota(order.begin(), order.end(), 0u);
      std::rotate(order.begin() + 10, order.begin() + 11, order.begin() + 11 + std::ptrdiff_t(distance));
      const std::vector<std::uint32_t> previous = order;
      const bool done = sort.rerank(keys.data(), n, order.data(), sorted.data(), scratch.data(), order_scratch.data());
      CAPTURE(pbrfit::kernel_set_name(set), distance);
      CHECK(done == (distance <= 32));
      if (done) {
        for (std::size_t r = 0; r < n; ++r) CHECK(order[r] == r);
      } else {
        CHECK(order == previous);
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
    // Small steps away and back (re-ranks) and far matrices (the full ranking), then m again.
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
