// The projection sort (projection_sort.hpp) of one kernel set. Included once by each
// projection_sort_isa_<set>.cpp, inside a namespace named by PBRFIT_KERNEL_ISA, so that the sets' copies never
// meet at link time. GCC and clang vector extensions, W doubles wide: the set's native register width.
#ifndef PBRFIT_KERNEL_ISA
#error "projection_sort_kernels.hpp is included by the projection_sort_isa_<set>.cpp files only"
#endif
#include <cstring>
#include <limits>

#include "projection_sort.hpp"

namespace pbrfit::ltc::detail::PBRFIT_KERNEL_ISA {

namespace {

#if defined(__AVX512F__)
constexpr int W = 8;
#elif defined(__AVX2__)
constexpr int W = 4;
#else
constexpr int W = 2;
#endif
using Doubles = double __attribute__((vector_size(W * sizeof(double))));
using Counts = std::int64_t __attribute__((vector_size(W * sizeof(std::int64_t))));  // comparisons give -1 / 0

// The ranks of the W indices first .. first + W - 1 (lanes past n hold +inf and are not used).
Counts ranks_of(const double* keys, std::size_t n, std::size_t first) {
  const std::size_t count = n - first < std::size_t(W) ? n - first : std::size_t(W);
  Doubles own;
  if (count == std::size_t(W)) {
    std::memcpy(&own, keys + first, sizeof own);
  } else {
    for (int l = 0; l < W; ++l)
      own[l] = std::size_t(l) < count ? keys[first + std::size_t(l)] : std::numeric_limits<double>::infinity();
  }
  // Two counters, so that consecutive comparisons do not wait on one another.
  Counts a = {}, b = {};
  std::size_t j = 0;
  for (; j + 1 < first; j += 2) {  // smaller indices: an equal key ranks before
    a -= (Counts)(keys[j] <= own);
    b -= (Counts)(keys[j + 1] <= own);
  }
  for (; j < first; ++j) a -= (Counts)(keys[j] <= own);
  Counts lane = {};
  for (int l = 0; l < W; ++l) lane[l] = l;
  for (; j < first + count; ++j) {  // the group itself: an equal key ranks before where its index is smaller
    const double other = keys[j];
    const Counts position = Counts{} + std::int64_t(j - first);
    a -= (Counts)(other < own) | ((Counts)(other == own) & (Counts)(position < lane));
  }
  for (; j + 1 < n; j += 2) {  // larger indices: only a smaller key ranks before
    a -= (Counts)(keys[j] < own);
    b -= (Counts)(keys[j + 1] < own);
  }
  for (; j < n; ++j) a -= (Counts)(keys[j] < own);
  return a + b;
}

}  // namespace

[[gnu::flatten]] void rank_sort(const double* keys, const double* values, std::size_t n, double* sorted,
                                std::uint32_t* order) {
  for (std::size_t first = 0; first < n; first += W) {
    const Counts rank = ranks_of(keys, n, first);
    for (int l = 0; l < W && first + std::size_t(l) < n; ++l) {
      const auto r = static_cast<std::size_t>(rank[l]);
      sorted[r] = values[first + std::size_t(l)];
      order[r] = static_cast<std::uint32_t>(first + std::size_t(l));
    }
  }
}

}  // namespace pbrfit::ltc::detail::PBRFIT_KERNEL_ISA
