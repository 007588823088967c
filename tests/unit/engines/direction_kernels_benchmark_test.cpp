// The LTC fit's direction kernels timed on one core, in the kernel set the process chose, as the LTC fit
// error feeds them (groups of 64 directions): the GGX lobe's evaluate_many and the LTC's transform_many and
// pdf_many. Prints directions per second, to set beside bench_machine_peak's division and square-root rates
// (docs/BENCHMARKS.md, "Kernels against the machine's peak"). Hidden: run with
//   test_engines "[.benchmark]"
#include <catch2/catch_test_macros.hpp>

#include <array>
#include <chrono>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "pbrfit/brdf/ggx_lobe.hpp"
#include "pbrfit/core/kernel_set.hpp"
#include "pbrfit/ltc/clamped_cosine.hpp"
#include "pbrfit/ltc/distribution.hpp"
#include "pbrfit/ltc/point_sets.hpp"

using namespace pbrfit;

namespace {

// Directions per second of `group` (which handles 64 directions), best of 5 passes of about 0.2 s.
double directions_per_second(const std::function<void()>& group) {
  double best = 0.0;
  for (int pass = 0; pass < 5; ++pass) {
    long groups = 0;
    const auto start = std::chrono::steady_clock::now();
    double seconds = 0.0;
    do {
      for (int i = 0; i < 256; ++i) group();
      groups += 256;
      seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    } while (seconds < 0.2);
    best = std::max(best, 64.0 * double(groups) / seconds);
  }
  return best;
}

}  // namespace

TEST_CASE("direction kernels of the LTC fit, directions per second", "[.benchmark]") {
  constexpr std::size_t n = 64;
  std::vector<Vector3> base, directions(n);
  std::vector<brdf::Lobe::Evaluation> evaluations(n);
  std::array<double, n> pdf{};
  for (const auto& [u1, u2] : ltc::golden_lattice(n)) base.push_back(ltc::sample_clamped_cosine(u1, u2));
  const brdf::GgxLobe lobe(0.3, 0.7);
  Matrix3 m;
  m << 0.6, 0.0, 0.2, 0.0, 0.5, 0.0, -0.1, 0.0, 1.0;
  const ltc::LtcDistribution distribution(m, 1.0);
  distribution.transform_many(base, directions, pdf);

  const double ggx = directions_per_second([&] { lobe.evaluate_many(directions, evaluations); });
  const double transform = directions_per_second([&] { distribution.transform_many(base, directions, pdf); });
  const double density = directions_per_second([&] { distribution.pdf_many(directions, pdf); });
  std::printf("kernel set %s: GgxLobe::evaluate_many %.3g, LtcDistribution::transform_many %.3g, pdf_many %.3g "
              "directions/s\n",
              std::string(kernel_set_name(active_kernel_set())).c_str(), ggx, transform, density);
  CHECK(ggx > 0.0);
  for (const auto& e : evaluations) CHECK(e.pdf >= 0.0);
}
