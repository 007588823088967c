// The 128 x 128 split-sum table of the demo job, timed on one core. Hidden: run with
//   test_engines "[.benchmark]"
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>

#include "pbrfit/brdf/roughness.hpp"
#include "pbrfit/brdf/split_sum_dfg.hpp"

using namespace pbrfit::brdf;

TEST_CASE("128 x 128 DFG table at 1e-6", "[.benchmark]") {
  constexpr int size = 128;
  for (SmithVisibility visibility :
       {SmithVisibility::height_correlated, SmithVisibility::separable, SmithVisibility::separable_schlick}) {
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpu_start = std::clock();
    double total_evaluations = 0.0;
    std::size_t max_evaluations = 0;
    double max_error = 0.0;
    bool all_converged = true;
    for (int row = 0; row < size; ++row) {
      const double alpha = alpha_from(RoughnessParametrization::perceptual, (row + 0.5) / size);
      for (int column = 0; column < size; ++column) {
        const DfgEntry entry = integrate_dfg((column + 0.5) / size, alpha, visibility, {});
        total_evaluations += static_cast<double>(entry.evaluations);
        max_evaluations = std::max(max_evaluations, entry.evaluations);
        max_error = std::max(max_error, entry.error_estimate);
        all_converged = all_converged && entry.converged;
      }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double cpu_seconds = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    std::printf("visibility %d: %.3f s wall, %.3f s cpu, evaluations per entry mean %.0f max %zu, max error estimate %.3g\n",
                static_cast<int>(visibility), seconds, cpu_seconds, total_evaluations / (size * size), max_evaluations, max_error);
    CHECK(all_converged);
    CHECK(max_error <= 1e-6);
  }
}
