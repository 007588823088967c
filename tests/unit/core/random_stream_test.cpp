#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <set>

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
