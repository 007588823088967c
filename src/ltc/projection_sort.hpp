#pragma once
// Internal: sorting one axis' projections for the sliced Wasserstein distance (sliced_wasserstein.hpp), as
// branch-free vector code in each kernel set (core/kernel_set.hpp).
//
// Contract: rank(keys, values, n, sorted, order) orders the indices 0..n-1 by (keys[k], k) ascending, a strict
// total order, and writes order[r] = the index of rank r and sorted[r] = values[order[r]]. Keys must hold no
// NaN (the caller maps NaN to +inf); -0 and +0 are equal keys, so they rank by index. The permutation is a
// function of the keys alone, the same in every set, and the same as any other sort by (key, index) gives, so
// a caller may mix this with an insertion sort on the same order and stay bitwise reproducible.
// n < 2^32; nothing is allocated.
//
// Each index's rank is counted, not found by comparison and exchange: rank(k) = #{j : (key_j, j) < (key_k, k)},
// n^2 comparisons, W lanes at a time (W = 8 doubles with AVX-512, 4 with AVX2, 2 with SSE2). For n = 128 that is
// about 0.85 us with AVX-512 on the EPYC machine (docs/BENCHMARKS.md), against 1-5 us for std::sort or an
// insertion sort that moves many samples; an insertion sort that moves only a few stays faster, so
// insertion_budget says how many moves an insertion sort may spend before this is the cheaper way.
#include <cstddef>
#include <cstdint>

#include "pbrfit/core/kernel_set.hpp"

namespace pbrfit::ltc::detail {

struct ProjectionSort {
  void (*rank)(const double* keys, const double* values, std::size_t n, double* sorted, std::uint32_t* order);
  std::size_t insertion_budget;  // moves, measured per set against rank() at n = 128
};

#define PBRFIT_DECLARE_PROJECTION_SORT(set)                                                                   \
  namespace set {                                                                                           \
  void rank_sort(const double* keys, const double* values, std::size_t n, double* sorted, std::uint32_t* order); \
  }
PBRFIT_DECLARE_PROJECTION_SORT(generic)
PBRFIT_DECLARE_PROJECTION_SORT(avx2)
PBRFIT_DECLARE_PROJECTION_SORT(avx512)
#undef PBRFIT_DECLARE_PROJECTION_SORT

inline ProjectionSort projection_sort(KernelSet set) {
  switch (set) {
#if defined(PBRFIT_X86_KERNELS)
    case KernelSet::avx512: return {avx512::rank_sort, 200};
    case KernelSet::avx2: return {avx2::rank_sort, 300};
#endif
    default: return {generic::rank_sort, 800};
  }
}

}  // namespace pbrfit::ltc::detail
