// bench_projection_sort: the sliced Wasserstein distance's sorts (docs/BENCHMARKS.md, "The eBRDF's
// sliced-Wasserstein sorts as vector code"), in every kernel set of this build and machine:
//   rank     the projection sort kernel (src/ltc/projection_sort.hpp) on n fresh keys,
//   rerank   the re-rank from a previous order whose samples moved at most 8 places (blocks of 9 shuffled), as
//            most of an optimizer's steps leave them (the order copied in included),
//   std      std::sort of the indices by (key, index), the order the kernel must give,
//   ctor     a SlicedWasserstein on 32 axes built and evaluated once (as each eBRDF fit's error is),
//   descent  the 30-step gradient descent of one eBRDF fit on 12 axes (fit_ltc_by_descent),
// each the best of 5 passes, in microseconds. The keys are normal pseudo-random numbers; the targets are
// samples of a skewed LTC, so the descent moves the way a real fit does.
// Usage: bench_projection_sort [n = 128]
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "pbrfit/core/kernel_set.hpp"
#include "pbrfit/ltc/descent_fit.hpp"
#include "pbrfit/ltc/distribution.hpp"
#include "pbrfit/ltc/sliced_wasserstein.hpp"
#include "projection_sort.hpp"

using namespace pbrfit;

namespace {

// The best of 5 passes of `pass` (which runs `count` repetitions), in microseconds per repetition.
double best_us(int count, const std::function<void()>& pass) {
  double best = 1e300;
  for (int p = 0; p < 5; ++p) {
    const auto start = std::chrono::steady_clock::now();
    pass();
    best = std::min(best, std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
  }
  return best / count;
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t n = argc > 1 ? std::size_t(std::strtoul(argv[1], nullptr, 10)) : 128;
  if (n == 0 || n > 100000) {
    std::fprintf(stderr, "bench_projection_sort: n must be 1..100000\n");
    return 2;
  }
  std::mt19937_64 random(1);
  std::normal_distribution<double> normal;
  constexpr int key_sets = 64;
  std::vector<double> keys(key_sets * n);
  for (double& k : keys) k = normal(random);

  Matrix3 skew;
  skew << 0.35, 0.1, 0.05, 0.0, 0.2, 0.0, 0.15, 0.0, 1.0;
  const ltc::LtcDistribution lobe(skew);
  std::uniform_real_distribution<double> uniform;
  std::vector<Vector3> targets(n);
  for (Vector3& t : targets) t = lobe.sample(uniform(random), uniform(random));

  // Each key set's order by (key, index), shuffled within blocks of 9 places.
  std::vector<std::uint32_t> near(key_sets * n);
  for (int key_set = 0; key_set < key_sets; ++key_set) {
    const double* k = keys.data() + std::size_t(key_set) * n;
    const auto first = near.begin() + std::ptrdiff_t(std::size_t(key_set) * n);
    std::iota(first, first + std::ptrdiff_t(n), 0u);
    std::sort(first, first + std::ptrdiff_t(n), [&](std::uint32_t a, std::uint32_t b) { return k[a] < k[b]; });
    for (std::size_t block = 0; block < n; block += 9)
      std::shuffle(first + std::ptrdiff_t(block), first + std::ptrdiff_t(std::min(n, block + 9)), random);
  }

  std::printf("n = %zu; microseconds, best of 5 passes\n\n| kernel set | rank | rerank, moves within 8 | std::sort | "
              "ctor + distance, 32 axes | descent fit, 30 steps on 12 axes |\n|---|---|---|---|---|---|\n", n);
  for (const KernelSet set : kernel_sets_available()) {
    use_kernel_set(set);
    const auto sort = ltc::detail::projection_sort(set);
    std::vector<double> sorted(n);
    std::vector<std::uint32_t> order(n);
    double sink = 0.0;
    const int sorts = 20000;
    const double rank_us = best_us(sorts, [&] {
      for (int r = 0; r < sorts; ++r) {
        const double* k = keys.data() + std::size_t(r % key_sets) * n;
        sort.rank(k, k, n, sorted.data(), order.data());
        sink += sorted[0];
      }
    });
    std::vector<double> scratch(ltc::detail::rerank_scratch(n));
    std::vector<std::uint32_t> order_scratch(n);
    const double rerank_us = best_us(sorts, [&] {
      for (int r = 0; r < sorts; ++r) {
        const std::size_t offset = std::size_t(r % key_sets) * n;
        std::copy(near.begin() + std::ptrdiff_t(offset), near.begin() + std::ptrdiff_t(offset + n), order.begin());
        if (!sort.rerank(keys.data() + offset, n, order.data(), sorted.data(), scratch.data(), order_scratch.data()))
          std::abort();  // blocks of 9 always fit the 8-window
        sink += sorted[0];
      }
    });
    const double std_us = best_us(sorts, [&] {
      for (int r = 0; r < sorts; ++r) {
        const double* k = keys.data() + std::size_t(r % key_sets) * n;
        std::iota(order.begin(), order.end(), 0u);
        std::sort(order.begin(), order.end(),
                  [&](std::uint32_t a, std::uint32_t b) { return k[a] < k[b] || (k[a] == k[b] && a < b); });
        sink += k[order[0]];
      }
    });
    const int builds = 500;
    const double ctor_us = best_us(builds, [&] {
      for (int r = 0; r < builds; ++r) sink += ltc::SlicedWasserstein(targets, 32).distance(skew);
    });
    const int fits = 100;
    const double descent_us = best_us(fits, [&] {
      for (int r = 0; r < fits; ++r) sink += ltc::fit_ltc_by_descent(targets, 1.0, nullptr, {}).distance;
    });
    std::printf("| %s | %.2f | %.2f | %.2f | %.1f | %.0f |\n", std::string(kernel_set_name(set)).c_str(), rank_us,
                rerank_us, std_us, ctor_us, descent_us);
    if (sink == 0.12345) std::printf(" ");  // keeps the work observable
  }
  return 0;
}
