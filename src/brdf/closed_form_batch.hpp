#pragma once
// Internal: the rho of closed-form lobes whose formulas need exp, log or erfc (Charlie sheen, sheen.hpp;
// Beckmann, beckmann.hpp) over many directions for one view, as vector code in each kernel set
// (core/kernel_set.hpp).
//
// Contract: charlie_batch(set)(view, l, n, out) and beckmann_batch(set)(view, l, n, out) set out[i] = rho(l[i])
// for i < n. Powers are exp(p log x) and exponentials Eigen's vector exp and log (erfc stays libm's, lane by
// lane), so a value may differ from the std::pow and std::exp form of the headers' formulas and between sets
// in the last bits (relative 1e-13 for Charlie at alpha = 1e-3, whose exponent reaches 500), never with a
// direction's place among the others or their number: directions go 16 at a time, the last group padded
// with copies, and one direction alone through a group of 2, whose packets run the same operations. rho is exactly 0 below either horizon, for l = -v and where the lobe's
// distribution vanishes (Charlie at h = n).
#include <cstddef>

#include "pbrfit/core/kernel_set.hpp"
#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::brdf::detail {

// What a CharlieView fixes.
struct CharlieConstants {
  double inverse_alpha;  // 1 / alpha
  double view_x, view_y, view_z;
  double view_lambda;    // Lambda(v)
  double fit[5];         // a, b, c, d, e of L(x) at this alpha
  double l_half;         // L(1/2)
};

// What a BeckmannView fixes.
struct BeckmannConstants {
  double alpha;
  double view_x, view_y, view_z;
  double view_lambda;  // Lambda(v)
};

template <class Constants>
using ClosedFormBatch = void (*)(const Constants& view, const Vector3* l, std::size_t n, double* out);

#define PBRFIT_DECLARE_CLOSED_FORM_BATCH(set)                                                      \
  namespace set {                                                                                  \
  void charlie_batch(const CharlieConstants& view, const Vector3* l, std::size_t n, double* out);   \
  void beckmann_batch(const BeckmannConstants& view, const Vector3* l, std::size_t n, double* out); \
  }
PBRFIT_DECLARE_CLOSED_FORM_BATCH(generic)
PBRFIT_DECLARE_CLOSED_FORM_BATCH(avx2)
PBRFIT_DECLARE_CLOSED_FORM_BATCH(avx512)
#undef PBRFIT_DECLARE_CLOSED_FORM_BATCH

inline ClosedFormBatch<CharlieConstants> charlie_batch(KernelSet set) {
  switch (set) {
#if defined(PBRFIT_X86_KERNELS)
    case KernelSet::avx512: return avx512::charlie_batch;
    case KernelSet::avx2: return avx2::charlie_batch;
#endif
    default: return generic::charlie_batch;
  }
}

inline ClosedFormBatch<BeckmannConstants> beckmann_batch(KernelSet set) {
  switch (set) {
#if defined(PBRFIT_X86_KERNELS)
    case KernelSet::avx512: return avx512::beckmann_batch;
    case KernelSet::avx2: return avx2::beckmann_batch;
#endif
    default: return generic::beckmann_batch;
  }
}

}  // namespace pbrfit::brdf::detail
