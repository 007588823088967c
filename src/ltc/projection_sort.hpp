#pragma once
// Internal: sorting one axis' projections for the sliced Wasserstein distance (sliced_wasserstein.hpp), as
// branch-free vector code in each kernel set (core/kernel_set.hpp).
//
// Contract: rank(keys, values, n, sorted, order) orders the indices 0..n-1 by (keys[k], k) ascending, a strict
// total order, and writes order[r] = the index of rank r and sorted[r] = values[order[r]]. Keys must hold no
// NaN (the caller maps NaN to +inf); -0 and +0 are equal keys, so they rank by index. The permutation is a
// function of the keys alone, the same in every set, and the same as any other sort by (key, index) gives, so
// a caller may mix it with rerank on the same order and stay bitwise reproducible.
// n < 2^32; nothing is allocated.
//
// Each index's rank is counted, not found by comparison and exchange: rank(k) = #{j : (key_j, j) < (key_k, k)},
// n^2 comparisons, W lanes at a time (W = 8 doubles with AVX-512, 4 with AVX2, 2 with SSE2). For n = 128 that is
// about 0.85 us with AVX-512 on the EPYC machine (docs/BENCHMARKS.md), against 1-5 us for std::sort.
//
// Contract: rerank(values, n, order, sorted, keys_scratch, order_scratch) re-sorts from a previous permutation
// in `order` when every inversion of it is short: with v_i = values[order[i]], it tries windows w = 8, 16, 32 and takes the smallest
// for which every key is strictly above all keys more than w places before it (so no pair further apart than
// w is out of order, and no such pair ties). Then rank_i = i - w + #{j in [i - w, i + w] : v_j < v_i} (keys
// past either end count as -inf before and +inf after), 2w comparisons instead of n; if the ranks sum to
// n (n - 1) / 2 no two keys in a window tied, the ranks are the permutation by key alone, which is the one by
// (key, index), and it writes order and sorted (= v in that order) and returns true. Otherwise (no window
// fits, or a tie) it returns false and leaves order as it was (sorted is then scratch). Keys must hold no NaN;
// keys_scratch holds rerank_scratch(n) doubles, order_scratch n indices. An optimizer's successive matrices
// move most samples a few places: in the eBRDF descent 69 % of re-sorts fit the 8-window and 83 % the
// 32-window (docs/BENCHMARKS.md).
#include <cstddef>
#include <cstdint>

#include "pbrfit/core/kernel_set.hpp"

namespace pbrfit::ltc::detail {

// The keys' padding before and after the re-rank's window (at least the largest window plus one, and after it
// also the widest register), and its scratch space: the padded keys and their running maxima.
inline constexpr std::size_t rerank_padding = 40;
inline constexpr std::size_t rerank_scratch(std::size_t n) { return 2 * n + 4 * rerank_padding; }

struct ProjectionSort {
  // values[k] = (axis[0] x[k] + axis[1] y[k]) + axis[2] z[k], as Eigen's dot of two 3-vectors rounds it (no
  // contraction); true if any is NaN.
  bool (*project)(const double* axis, const double* x, const double* y, const double* z, std::size_t n,
                  double* values);
  // The gradient's per-sample sums: sums[c n + k] += signs[k] * axis[c] for c < 3 and sums[3 n + k] +=
  // signs[k] * values[k], one multiply and one add each (no contraction).
  void (*add_signed)(const double* signs, const double* values, const double* axis, std::size_t n, double* sums);
  void (*rank)(const double* keys, const double* values, std::size_t n, double* sorted, std::uint32_t* order);
  bool (*rerank)(const double* values, std::size_t n, std::uint32_t* order, double* sorted, double* keys_scratch,
                 std::uint32_t* order_scratch);
};

#define PBRFIT_DECLARE_PROJECTION_SORT(set)                                                                   \
  namespace set {                                                                                           \
  bool project(const double* axis, const double* x, const double* y, const double* z, std::size_t n,             \
               double* values);                                                                                 \
  void add_signed(const double* signs, const double* values, const double* axis, std::size_t n, double* sums);   \
  void rank_sort(const double* keys, const double* values, std::size_t n, double* sorted, std::uint32_t* order); \
  bool rerank(const double* values, std::size_t n, std::uint32_t* order, double* sorted, double* keys_scratch,   \
              std::uint32_t* order_scratch);                                                                    \
  }
PBRFIT_DECLARE_PROJECTION_SORT(generic)
PBRFIT_DECLARE_PROJECTION_SORT(avx2)
PBRFIT_DECLARE_PROJECTION_SORT(avx512)
#undef PBRFIT_DECLARE_PROJECTION_SORT

inline ProjectionSort projection_sort(KernelSet set) {
  switch (set) {
#if defined(PBRFIT_X86_KERNELS)
    case KernelSet::avx512: return {avx512::project, avx512::add_signed, avx512::rank_sort, avx512::rerank};
    case KernelSet::avx2: return {avx2::project, avx2::add_signed, avx2::rank_sort, avx2::rerank};
#endif
    default: return {generic::project, generic::add_signed, generic::rank_sort, generic::rerank};
  }
}

}  // namespace pbrfit::ltc::detail
