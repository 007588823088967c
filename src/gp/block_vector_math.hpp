// The inverse and tangent trigonometric operators (tan, asin, acos, atan) over one chunk of a block in the
// avx2 and avx512 kernel sets, by glibc's vector math library (libmvec, glibc 2.35 and later). Eigen 3.4
// has no vector code for them: it calls the C library once per lane, which made tan and acos 40 % of a
// metal search's time.
//
// Contract:
//  - Included by block_kernels.hpp in the files of the sets that define PBRFIT_KERNEL_LIBMVEC (256 for
//    avx2, 512 for avx512), into the set's own namespace; the generic set keeps the C library's scalar
//    functions.
//  - The entry points are the x86-64 vector function ABI's (_ZGVd: AVX2, _ZGVe: AVX-512). Each picks its
//    code from the CPU once, at load: AVX2 with FMA for _ZGVd, AVX-512 DQ for _ZGVe, exactly what the set
//    itself requires (core/kernel_set.hpp), so a set's values are the same on every CPU that runs the set
//    with the same glibc (unless GLIBC_TUNABLES sets glibc.cpu.hwcaps=MathVec_Prefer_No_AVX512, which
//    makes _ZGVe take its AVX2 code).
//  - Results are within a few ulps of the C library's (test "Kernel sets differ from the generic one only
//    in transcendentals, by a few ulps"); a lane's value depends on that lane's input only.
#pragma once
#include <immintrin.h>

#include <cstddef>
#include <cstring>

#include "pbrfit/gp/opcode.hpp"

namespace pbrfit::gp::detail::PBRFIT_KERNEL_ISA {

#if PBRFIT_KERNEL_LIBMVEC == 512
#define PBRFIT_LIBMVEC_FLOATS(fn) _ZGVeN16v_##fn##f
#define PBRFIT_LIBMVEC_DOUBLES(fn) _ZGVeN8v_##fn
using LibmvecFloats = __m512;
using LibmvecDoubles = __m512d;
#elif PBRFIT_KERNEL_LIBMVEC == 256
#define PBRFIT_LIBMVEC_FLOATS(fn) _ZGVdN8v_##fn##f
#define PBRFIT_LIBMVEC_DOUBLES(fn) _ZGVdN4v_##fn
using LibmvecFloats = __m256;
using LibmvecDoubles = __m256d;
#else
#error "PBRFIT_KERNEL_LIBMVEC must be 256 or 512"
#endif

#define PBRFIT_DECLARE_LIBMVEC(fn)                                     \
  LibmvecFloats PBRFIT_LIBMVEC_FLOATS(fn)(LibmvecFloats) noexcept;     \
  LibmvecDoubles PBRFIT_LIBMVEC_DOUBLES(fn)(LibmvecDoubles) noexcept;
extern "C" {
PBRFIT_DECLARE_LIBMVEC(tan)
PBRFIT_DECLARE_LIBMVEC(asin)
PBRFIT_DECLARE_LIBMVEC(acos)
PBRFIT_DECLARE_LIBMVEC(atan)
}
#undef PBRFIT_DECLARE_LIBMVEC

// f over `size` values, one vector register at a time (size a multiple of the register's lanes).
template <std::size_t size, class V, class T>
inline void libmvec_map(V (*f)(V) noexcept, const T* a, T* out) {
  constexpr std::size_t lanes = sizeof(V) / sizeof(T);
  static_assert(size % lanes == 0);
  for (std::size_t i = 0; i < size; i += lanes) {
    V v;
    std::memcpy(&v, a + i, sizeof v);
    v = f(v);
    std::memcpy(out + i, &v, sizeof v);
  }
}

// out = op(a) over `size` values when libmvec computes op here; false (nothing written) otherwise.
template <std::size_t size, class T>
inline bool libmvec_chunk(Opcode op, const T* a, T* out) {
#define PBRFIT_LIBMVEC_CASE(fn)                                                               \
  case Opcode::fn:                                                                            \
    if constexpr (sizeof(T) == sizeof(float)) libmvec_map<size>(PBRFIT_LIBMVEC_FLOATS(fn), a, out); \
    else libmvec_map<size>(PBRFIT_LIBMVEC_DOUBLES(fn), a, out);                                \
    return true;
  switch (op) {
    PBRFIT_LIBMVEC_CASE(tan)
    PBRFIT_LIBMVEC_CASE(asin)
    PBRFIT_LIBMVEC_CASE(acos)
    PBRFIT_LIBMVEC_CASE(atan)
    default:
      return false;
  }
#undef PBRFIT_LIBMVEC_CASE
}

}  // namespace pbrfit::gp::detail::PBRFIT_KERNEL_ISA

#undef PBRFIT_LIBMVEC_FLOATS
#undef PBRFIT_LIBMVEC_DOUBLES
