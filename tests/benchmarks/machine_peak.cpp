// bench_machine_peak: what one core of this machine can do, measured, as the yardstick for the hot kernels'
// throughput (docs/BENCHMARKS.md, "Kernels against the machine's peak"). Each line runs one instruction
// kind on 16 independent register chains (enough to cover its latency), so only the execution units'
// throughput limits it, in the widest vectors of each kernel set:
//   add+mul  an add and a multiply per chain and step (what the GP interpreter's arithmetic needs),
//   fma      a fused multiply-add per chain and step, counted as 2 operations,
//   div, sqrt
// for float32 and float64 lanes. Figures are lane operations per second, best of 5 passes, at whatever
// clock the machine runs (divided by the clock they give operations per cycle). Built without contraction
// into FMA, so the add + mul line stays two instructions.
//
// Usage: bench_machine_peak [milliseconds per pass, default 200]
#include <immintrin.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>

namespace {

constexpr int chains = 16;

using Clock = std::chrono::steady_clock;

// The best of 5 passes of `run(steps)` (returning lane operations done), each about `ms` long.
double best_rate(const std::function<double(long)>& run, double ms) {
  long steps = 1000;
  for (;;) {  // size a pass
    const auto t0 = Clock::now();
    run(steps);
    const double s = std::chrono::duration<double>(Clock::now() - t0).count();
    if (s > ms * 1e-3 / 4) {
      steps = long(double(steps) * ms * 1e-3 / s);
      break;
    }
    if (steps > (1L << 40)) {
      std::fprintf(stderr, "bench_machine_peak: a kernel takes no time: the compiler removed its loop\n");
      std::exit(1);
    }
    steps *= 4;
  }
  double best = 0.0;
  for (int pass = 0; pass < 5; ++pass) {
    const auto t0 = Clock::now();
    const double ops = run(steps);
    const double s = std::chrono::duration<double>(Clock::now() - t0).count();
    best = std::max(best, ops / s);
  }
  return best;
}

volatile double sink = 0.0;

// One kernel per (width, type, operation): V is the register type, L its lanes.
// opaque(v) keeps the compiler from reasoning about a chain's value (it folded whole loops away): no
// instruction, the value just has to be in a vector register after every step (declared per set, so the
// register's width is one the function's target has).
#define PEAK_KERNELS(target_attr, prefix, V, L, setone, add, mul, fmadd, div, sqrt_, reduce)                  \
  __attribute__((target(target_attr), always_inline)) inline void prefix##_opaque(V& v) {                     \
    asm volatile("" : "+v"(v));                                                                              \
  }                                                                                                          \
  __attribute__((target(target_attr), noinline)) double prefix##_add_mul(long steps) {                       \
    V acc[chains];                                                                                           \
    for (int c = 0; c < chains; ++c) acc[c] = setone(1.0 + 1e-9 * c);                                        \
    const V m = setone(0.9999999), a = setone(1e-7);                                                         \
    for (long s = 0; s < steps; ++s)                                                                         \
      for (int c = 0; c < chains; ++c) { acc[c] = add(mul(acc[c], m), a); prefix##_opaque(acc[c]); }                                     \
    for (int c = 0; c < chains; ++c) sink = sink + reduce(acc[c]);                                           \
    return 2.0 * L * chains * double(steps);                                                                 \
  }                                                                                                          \
  __attribute__((target(target_attr), noinline)) double prefix##_fma(long steps) {                           \
    V acc[chains];                                                                                           \
    for (int c = 0; c < chains; ++c) acc[c] = setone(1.0 + 1e-9 * c);                                        \
    const V m = setone(0.9999999), a = setone(1e-7);                                                         \
    for (long s = 0; s < steps; ++s)                                                                         \
      for (int c = 0; c < chains; ++c) { acc[c] = fmadd(acc[c], m, a); prefix##_opaque(acc[c]); }                                         \
    for (int c = 0; c < chains; ++c) sink = sink + reduce(acc[c]);                                           \
    return 2.0 * L * chains * double(steps);                                                                 \
  }                                                                                                          \
  __attribute__((target(target_attr), noinline)) double prefix##_div(long steps) {                           \
    V acc[chains];                                                                                           \
    for (int c = 0; c < chains; ++c) acc[c] = setone(1.0 + 1e-9 * c);                                        \
    const V d = setone(1.0000001);                                                                           \
    for (long s = 0; s < steps; ++s)                                                                         \
      for (int c = 0; c < chains; ++c) { acc[c] = div(acc[c], d); prefix##_opaque(acc[c]); }                                              \
    for (int c = 0; c < chains; ++c) sink = sink + reduce(acc[c]);                                           \
    return double(L) * chains * double(steps);                                                               \
  }                                                                                                          \
  __attribute__((target(target_attr), noinline)) double prefix##_sqrt(long steps) {                          \
    V acc[chains];                                                                                           \
    for (int c = 0; c < chains; ++c) acc[c] = setone(2.0 + 1e-9 * c);                                        \
    for (long s = 0; s < steps; ++s)                                                                         \
      for (int c = 0; c < chains; ++c) { acc[c] = sqrt_(acc[c]); prefix##_opaque(acc[c]); }                                               \
    for (int c = 0; c < chains; ++c) sink = sink + reduce(acc[c]);                                           \
    return double(L) * chains * double(steps);                                                               \
  }

__attribute__((target("avx512f"))) inline float sum16(__m512 v) { return _mm512_reduce_add_ps(v); }
__attribute__((target("avx512f"))) inline double sum8(__m512d v) { return _mm512_reduce_add_pd(v); }
__attribute__((target("avx2,fma"))) inline float sum8f(__m256 v) {
  alignas(32) float x[8];
  _mm256_store_ps(x, v);
  return x[0] + x[7];
}
__attribute__((target("avx2,fma"))) inline double sum4(__m256d v) {
  alignas(32) double x[4];
  _mm256_store_pd(x, v);
  return x[0] + x[3];
}
inline float sum4f(__m128 v) { return _mm_cvtss_f32(v); }
inline double sum2(__m128d v) { return _mm_cvtsd_f64(v); }
// SSE2 has no fused multiply-add: its line runs a multiply and an add, as the generic set's code does.
inline __m128 sse_fma_ps(__m128 a, __m128 b, __m128 c) { return _mm_add_ps(_mm_mul_ps(a, b), c); }
inline __m128d sse_fma_pd(__m128d a, __m128d b, __m128d c) { return _mm_add_pd(_mm_mul_pd(a, b), c); }
__attribute__((target("avx512f"))) inline __m512 set16(double x) { return _mm512_set1_ps(float(x)); }
__attribute__((target("avx512f"))) inline __m512d set8(double x) { return _mm512_set1_pd(x); }
__attribute__((target("avx2,fma"))) inline __m256 set8f(double x) { return _mm256_set1_ps(float(x)); }
__attribute__((target("avx2,fma"))) inline __m256d set4(double x) { return _mm256_set1_pd(x); }
inline __m128 set4f(double x) { return _mm_set1_ps(float(x)); }
inline __m128d set2(double x) { return _mm_set1_pd(x); }

PEAK_KERNELS("avx512f", z_f32, __m512, 16, set16, _mm512_add_ps, _mm512_mul_ps, _mm512_fmadd_ps, _mm512_div_ps,
             _mm512_sqrt_ps, sum16)
PEAK_KERNELS("avx512f", z_f64, __m512d, 8, set8, _mm512_add_pd, _mm512_mul_pd, _mm512_fmadd_pd, _mm512_div_pd,
             _mm512_sqrt_pd, sum8)
PEAK_KERNELS("avx2,fma", y_f32, __m256, 8, set8f, _mm256_add_ps, _mm256_mul_ps, _mm256_fmadd_ps, _mm256_div_ps,
             _mm256_sqrt_ps, sum8f)
PEAK_KERNELS("avx2,fma", y_f64, __m256d, 4, set4, _mm256_add_pd, _mm256_mul_pd, _mm256_fmadd_pd, _mm256_div_pd,
             _mm256_sqrt_pd, sum4)
PEAK_KERNELS("sse2", x_f32, __m128, 4, set4f, _mm_add_ps, _mm_mul_ps, sse_fma_ps, _mm_div_ps, _mm_sqrt_ps, sum4f)
PEAK_KERNELS("sse2", x_f64, __m128d, 2, set2, _mm_add_pd, _mm_mul_pd, sse_fma_pd, _mm_div_pd, _mm_sqrt_pd, sum2)

struct Row {
  const char* set;
  const char* type;
  double (*add_mul)(long), (*fma)(long), (*div)(long), (*sqrt)(long);
  bool (*available)();
};

bool always() { return true; }
bool has_avx2() { return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"); }
bool has_avx512() { return __builtin_cpu_supports("avx512f"); }

}  // namespace

int main(int argc, char** argv) {
  const double ms = argc > 1 ? std::atof(argv[1]) : 200.0;
  const Row rows[] = {
      {"generic (SSE2, 128-bit)", "float32", x_f32_add_mul, x_f32_fma, x_f32_div, x_f32_sqrt, always},
      {"generic (SSE2, 128-bit)", "float64", x_f64_add_mul, x_f64_fma, x_f64_div, x_f64_sqrt, always},
      {"avx2 (256-bit)", "float32", y_f32_add_mul, y_f32_fma, y_f32_div, y_f32_sqrt, has_avx2},
      {"avx2 (256-bit)", "float64", y_f64_add_mul, y_f64_fma, y_f64_div, y_f64_sqrt, has_avx2},
      {"avx512 (512-bit)", "float32", z_f32_add_mul, z_f32_fma, z_f32_div, z_f32_sqrt, has_avx512},
      {"avx512 (512-bit)", "float64", z_f64_add_mul, z_f64_fma, z_f64_div, z_f64_sqrt, has_avx512},
  };
  std::printf("| kernel set | lanes | add + mul, ops/s | fma (2 ops), ops/s | div, ops/s | sqrt, ops/s |\n");
  std::printf("|---|---|---|---|---|---|\n");
  for (const Row& row : rows) {
    if (!row.available()) {
      std::printf("| %s | %s | (not on this machine) | | | |\n", row.set, row.type);
      continue;
    }
    std::printf("| %s | %s | %.3g | %.3g | %.3g | %.3g |\n", row.set, row.type, best_rate(row.add_mul, ms),
                best_rate(row.fma, ms), best_rate(row.div, ms), best_rate(row.sqrt, ms));
    std::fflush(stdout);
  }
  return sink == 12345.0 ? 1 : 0;
}
