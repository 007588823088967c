// The projection sort (projection_sort.hpp) of one kernel set. Included once by each
// projection_sort_isa_<set>.cpp, inside a namespace named by PBRFIT_KERNEL_ISA, so that the sets' copies never
// meet at link time. GCC and clang vector extensions, W doubles wide: the set's native register width.
#ifndef PBRFIT_KERNEL_ISA
#error "projection_sort_kernels.hpp is included by the projection_sort_isa_<set>.cpp files only"
#endif
#include <algorithm>
#include <cstddef>
#include <cstring>
#if defined(__AVX512F__)
#include <immintrin.h>
#endif
#include <limits>
#include <utility>

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

// How many of keys[from .. to) are below own in each lane (OrEqual: at or below), and how many of the windows'
// keys v[-window .. -1] and v[1 .. window] are below own. With AVX-512 a comparison gives a mask that adds
// one where it is set (GCC 12 widens a vector-extension mask to a vector and subtracts it instead: twice the
// instructions); elsewhere the vector extensions' -1 / 0 lanes are subtracted.
#if defined(__AVX512F__)
template <bool OrEqual>
Counts count_below(const double* keys, std::size_t from, std::size_t to, Doubles own) {
  constexpr int predicate = OrEqual ? _CMP_GE_OQ : _CMP_GT_OQ;  // own >= key, own > key
  const __m512d o = (__m512d)own;
  const __m512i one = _mm512_set1_epi64(1);
  // Four counters, so that consecutive comparisons do not wait on one another.
  __m512i a = _mm512_setzero_si512(), b = a, c = a, d = a;
  std::size_t j = from;
  for (; j + 4 <= to; j += 4) {
    a = _mm512_mask_add_epi64(a, _mm512_cmp_pd_mask(o, _mm512_set1_pd(keys[j]), predicate), a, one);
    b = _mm512_mask_add_epi64(b, _mm512_cmp_pd_mask(o, _mm512_set1_pd(keys[j + 1]), predicate), b, one);
    c = _mm512_mask_add_epi64(c, _mm512_cmp_pd_mask(o, _mm512_set1_pd(keys[j + 2]), predicate), c, one);
    d = _mm512_mask_add_epi64(d, _mm512_cmp_pd_mask(o, _mm512_set1_pd(keys[j + 3]), predicate), d, one);
  }
  for (; j < to; ++j) a = _mm512_mask_add_epi64(a, _mm512_cmp_pd_mask(o, _mm512_set1_pd(keys[j]), predicate), a, one);
  return (Counts)_mm512_add_epi64(_mm512_add_epi64(a, b), _mm512_add_epi64(c, d));
}

template <int Window>
Counts count_window(const double* v, Doubles own) {
  const __m512d o = (__m512d)own;
  const __m512i one = _mm512_set1_epi64(1);
  __m512i a = _mm512_setzero_si512(), b = a;
  for (int d = 1; d <= Window; ++d) {
    a = _mm512_mask_add_epi64(a, _mm512_cmp_pd_mask(o, _mm512_loadu_pd(v - d), _CMP_GT_OQ), a, one);
    b = _mm512_mask_add_epi64(b, _mm512_cmp_pd_mask(o, _mm512_loadu_pd(v + d), _CMP_GT_OQ), b, one);
  }
  return (Counts)_mm512_add_epi64(a, b);
}
#else
template <bool OrEqual>
Counts count_below(const double* keys, std::size_t from, std::size_t to, Doubles own) {
  Counts a = {}, b = {};
  std::size_t j = from;
  for (; j + 2 <= to; j += 2) {
    if constexpr (OrEqual) {
      a -= (Counts)(keys[j] <= own);
      b -= (Counts)(keys[j + 1] <= own);
    } else {
      a -= (Counts)(keys[j] < own);
      b -= (Counts)(keys[j + 1] < own);
    }
  }
  for (; j < to; ++j) a -= OrEqual ? (Counts)(keys[j] <= own) : (Counts)(keys[j] < own);
  return a + b;
}

template <int Window>
Counts count_window(const double* v, Doubles own) {
  Counts a = {}, b = {};
  for (int d = 1; d <= Window; ++d) {
    Doubles before, after;
    std::memcpy(&before, v - d, sizeof before);
    std::memcpy(&after, v + d, sizeof after);
    a -= (Counts)(before < own);
    b -= (Counts)(after < own);
  }
  return a + b;
}
#endif

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
  // Smaller indices: an equal key ranks before; larger ones: only a smaller key.
  Counts below = count_below<true>(keys, 0, first, own) + count_below<false>(keys, first + count, n, own);
  Counts lane = {};
  for (int l = 0; l < W; ++l) lane[l] = l;
  for (std::size_t j = first; j < first + count; ++j) {  // the group itself: equal keys rank by index
    const double other = keys[j];
    const Counts position = Counts{} + std::int64_t(j - first);
    below -= (Counts)(other < own) | ((Counts)(other == own) & (Counts)(position < lane));
  }
  return below;
}

// x moved up by Shift lanes, the lowest Shift lanes taken from fill.
template <int Shift, std::size_t... L>
Doubles shifted_in(Doubles x, Doubles fill, std::index_sequence<L...>) {
  return __builtin_shufflevector(fill, x, (int(L) + W - Shift)...);
}
template <int Shift>
Doubles shifted_in(Doubles x, Doubles fill) {
  return shifted_in<Shift>(x, fill, std::make_index_sequence<W>{});
}

Doubles maximum(Doubles a, Doubles b) { return a > b ? a : b; }  // no NaN here

bool none(Counts mask) {
  std::int64_t any = 0;
  for (int l = 0; l < W; ++l) any |= mask[l];
  return any == 0;
}

// rerank's ranks of the W positions first .. first + W - 1 of the padded keys v, counted within Window places
// either side (lanes past n are NaN, which count nothing).
template <int Window>
Counts window_ranks(const double* v, std::size_t n, std::size_t first) {
  Doubles own;
  std::memcpy(&own, v + first, sizeof own);
  for (std::size_t l = n - first; l < std::size_t(W); ++l) own[l] = std::numeric_limits<double>::quiet_NaN();
  Counts lane = {};
  for (int l = 0; l < W; ++l) lane[l] = l;
  return count_window<Window>(v + first, own) + lane + (std::int64_t(first) - Window);
}

// rerank with the window chosen: ranks, their check, and the new order.
template <int Window>
bool rerank_within(const double* v, std::size_t n, std::uint32_t* order, double* sorted,
                   std::uint32_t* order_scratch) {
  std::uint64_t sum = 0;
  bool in_range = true;
  for (std::size_t first = 0; first < n; first += W) {
    const Counts rank = window_ranks<Window>(v, n, first);
    for (int l = 0; l < W && first + std::size_t(l) < n; ++l) {
      const auto r = static_cast<std::uint64_t>(rank[l]);
      in_range &= r < n;
      const std::size_t at = r < n ? r : 0;
      sum += r;
      sorted[at] = v[first + std::size_t(l)];
      order_scratch[at] = order[first + std::size_t(l)];
    }
  }
  if (!in_range || sum != std::uint64_t(n) * (n - 1) / 2) return false;
  std::memcpy(order, order_scratch, n * sizeof *order);
  return true;
}

}  // namespace

[[gnu::flatten]] bool project(const double* axis, const double* x, const double* y, const double* z,
                              std::size_t n, double* values) {
  const double a = axis[0], b = axis[1], c = axis[2];
  Counts nan = {};
  std::size_t k = 0;
  for (; k + W <= n; k += W) {
    Doubles px, py, pz;
    std::memcpy(&px, x + k, sizeof px);
    std::memcpy(&py, y + k, sizeof py);
    std::memcpy(&pz, z + k, sizeof pz);
    const Doubles value = (a * px + b * py) + c * pz;
    nan |= (Counts)(value != value);
    std::memcpy(values + k, &value, sizeof value);
  }
  bool any = !none(nan);
  for (; k < n; ++k) {
    values[k] = (a * x[k] + b * y[k]) + c * z[k];
    any |= values[k] != values[k];
  }
  return any;
}

[[gnu::flatten]] void add_signed(const double* signs, const double* values, const double* axis, std::size_t n,
                                 double* sums) {
  double* x = sums;
  double* y = sums + n;
  double* z = sums + 2 * n;
  double* projected = sums + 3 * n;
  const double a = axis[0], b = axis[1], c = axis[2];
  std::size_t k = 0;
  for (; k + W <= n; k += W) {
    Doubles sign, value, sx, sy, sz, sp;
    std::memcpy(&sign, signs + k, sizeof sign);
    std::memcpy(&value, values + k, sizeof value);
    std::memcpy(&sx, x + k, sizeof sx);
    std::memcpy(&sy, y + k, sizeof sy);
    std::memcpy(&sz, z + k, sizeof sz);
    std::memcpy(&sp, projected + k, sizeof sp);
    sx += sign * a;
    sy += sign * b;
    sz += sign * c;
    sp += sign * value;
    std::memcpy(x + k, &sx, sizeof sx);
    std::memcpy(y + k, &sy, sizeof sy);
    std::memcpy(z + k, &sz, sizeof sz);
    std::memcpy(projected + k, &sp, sizeof sp);
  }
  for (; k < n; ++k) {
    x[k] += signs[k] * a;
    y[k] += signs[k] * b;
    z[k] += signs[k] * c;
    projected[k] += signs[k] * values[k];
  }
}

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

[[gnu::flatten]] bool rerank(const double* values, std::size_t n, std::uint32_t* order, double* sorted,
                             double* keys_scratch, std::uint32_t* order_scratch) {
  constexpr double infinity = std::numeric_limits<double>::infinity();
  double* v = keys_scratch + rerank_padding;                  // the keys in the last order, padded
  double* running_max = v + n + 2 * rerank_padding;           // max(v[0..i]), -inf before the start
  for (std::size_t i = 0; i < rerank_padding; ++i) {
    v[std::ptrdiff_t(i) - std::ptrdiff_t(rerank_padding)] = -infinity;
    v[n + i] = infinity;
    running_max[std::ptrdiff_t(i) - std::ptrdiff_t(rerank_padding)] = -infinity;
  }
  for (std::size_t i = 0; i < n; ++i) v[i] = values[order[i]];
  // Running maxima a register at a time: within it by log2(W) shifted maxima, then the carry from before.
  const Doubles minus_infinity = Doubles{} - infinity;
  double carry = -infinity;
  for (std::size_t first = 0; first < n; first += W) {
    Doubles x;
    std::memcpy(&x, v + first, sizeof x);
    for (std::size_t l = n - first; l < std::size_t(W); ++l) x[l] = -infinity;
    x = maximum(x, shifted_in<1>(x, minus_infinity));
    if constexpr (W > 2) x = maximum(x, shifted_in<2>(x, minus_infinity));
    if constexpr (W > 4) x = maximum(x, shifted_in<4>(x, minus_infinity));
    x = maximum(x, Doubles{} + carry);
    carry = x[W - 1];
    std::memcpy(running_max + first, &x, sizeof x);
  }
  // A window w fits where every key is above the running maximum w + 1 places before it.
  Counts misfit_8 = {}, misfit_16 = {}, misfit_32 = {};
  for (std::size_t first = 0; first < n; first += W) {
    Doubles own, before_8, before_16, before_32;
    std::memcpy(&own, v + first, sizeof own);  // lanes past n are +inf: above everything
    std::memcpy(&before_8, running_max + first - 9, sizeof own);
    std::memcpy(&before_16, running_max + first - 17, sizeof own);
    std::memcpy(&before_32, running_max + first - 33, sizeof own);
    misfit_8 |= (Counts)(own <= before_8);
    misfit_16 |= (Counts)(own <= before_16);
    misfit_32 |= (Counts)(own <= before_32);
  }
  if (none(misfit_8)) return rerank_within<8>(v, n, order, sorted, order_scratch);
  if (none(misfit_16)) return rerank_within<16>(v, n, order, sorted, order_scratch);
  if (none(misfit_32)) return rerank_within<32>(v, n, order, sorted, order_scratch);
  return false;
}

}  // namespace pbrfit::ltc::detail::PBRFIT_KERNEL_ISA
