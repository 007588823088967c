#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <set>
#include <vector>

#include "pbrfit/core/error.hpp"
#include "pbrfit/core/random_stream.hpp"

using namespace pbrfit;

TEST_CASE("a random stream is a pure function of (seed, item, substream)") {
  RandomStream a(42, 7), b(42, 7);
  for (int i = 0; i < 100; ++i) CHECK(a.next_u64() == b.next_u64());
  std::set<std::uint64_t> firsts;
  for (std::uint64_t seed : {0, 1})
    for (std::uint64_t item : {0, 1, 2})
      for (std::uint64_t sub : {0, 1}) firsts.insert(RandomStream(seed, item, sub).next_u64());
  CHECK(firsts.size() == 12);
}

TEST_CASE("work-item streams differ for every seed, stage, item and substream: two epochs of one island never "
          "replay the same numbers") {
  std::set<std::uint64_t> firsts;
  for (std::uint64_t seed : {0, 1})
    for (std::uint32_t stage : {0u, 1u, 2u})
      for (std::uint64_t item : {0, 1, 2})
        for (std::uint64_t sub : {0, 1}) firsts.insert(RandomStream(seed, stage, item, sub).next_u64());
  CHECK(firsts.size() == 36);
  // The engines' (seed, index, substream) streams are a separate family.
  CHECK(RandomStream(0, 0u, 1, 0).next_u64() != RandomStream(0, 1, 0).next_u64());
  // Whole sequences differ too, not just their first numbers.
  RandomStream epoch0(5, 0u, 3, 0), epoch1(5, 1u, 3, 0);
  int same = 0;
  for (int i = 0; i < 1000; ++i) same += epoch0.next_u64() == epoch1.next_u64();
  CHECK(same == 0);
}

TEST_CASE("a derived stream depends on its parent's key, never on how much the parent has drawn") {
  RandomStream fresh(9, 4), used(9, 4);
  for (int i = 0; i < 17; ++i) used.next_u64();
  CHECK(fresh.derive(3).next_u64() == used.derive(3).next_u64());
  CHECK(fresh.derive(3).next_u64() != fresh.derive(4).next_u64());
  CHECK(fresh.derive(0).next_u64() != fresh.next_u64());
}

TEST_CASE("below(n) draws every value from 0 to n - 1 equally often") {
  RandomStream r(1, 2);
  const std::uint64_t n = 7;
  std::vector<int> counts(n, 0);
  const int draws = 70000;
  for (int i = 0; i < draws; ++i) {
    const auto v = r.below(n);
    REQUIRE(v < n);
    ++counts[v];
  }
  for (int c : counts) CHECK(std::abs(c - draws / 7) < 5 * std::sqrt(draws / 7.0));
  CHECK(RandomStream(3, 3).below(1) == 0);
}

TEST_CASE("uniform draws lie in the unit interval with the right mean and variance") {
  RandomStream r(3, 9);
  const int n = 200000;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    const double u = r.uniform();
    REQUIRE(u >= 0.0);
    REQUIRE(u < 1.0);
    sum += u;
    sum2 += u * u;
  }
  const double mean = sum / n, variance = sum2 / n - mean * mean;
  CHECK(std::abs(mean - 0.5) < 4 * std::sqrt(1.0 / 12 / n));
  CHECK(std::abs(variance - 1.0 / 12) < 1e-3);
}

TEST_CASE("input errors format as FILE:LINE:COL: error: MESSAGE") {
  CHECK(std::string(InputError({"job.yaml", 3, 7}, "bad").what()) == "job.yaml:3:7: error: bad");
  CHECK(std::string(InputError({"job.yaml", 3, 0}, "bad").what()) == "job.yaml:3: error: bad");
  CHECK(std::string(InputError({"x.h5"}, "bad").what()) == "x.h5: error: bad");
}
