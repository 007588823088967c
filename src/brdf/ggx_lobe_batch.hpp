#pragma once
// Internal: GgxLobe::evaluate over many directions, as vector code in each kernel set (core/kernel_set.hpp).
//
// Contract: ggx_lobe_batch(set)(lobe, l, n, out) sets out[i] = GgxLobe::evaluate(l[i]) for i < n, bit for
// bit in every set: the kernel has the scalar code's operations in its order (D and Lambda of ggx.cpp,
// |v + l| as sqrt((x^2 + y^2) + z^2), like Eigen's norm of a 3-vector), and arithmetic and sqrt round the same
// in every set (no contraction into FMA). Directions go 16 at a time, the last group padded with copies.
#include <cstddef>

#include "pbrfit/brdf/lobe.hpp"
#include "pbrfit/core/kernel_set.hpp"

namespace pbrfit::brdf::detail {

// What a GgxLobe fixes.
struct GgxLobeConstants {
  double alpha;
  double view_x, view_y, view_z;
  double view_lambda;  // Lambda(v)
  double masking;      // G1(v)
};

using GgxLobeBatch = void (*)(const GgxLobeConstants& lobe, const Vector3* l, std::size_t n,
                              Lobe::Evaluation* out);

#define PBRFIT_DECLARE_GGX_LOBE_BATCH(set) \
  namespace set {                          \
  void ggx_lobe_batch(const GgxLobeConstants& lobe, const Vector3* l, std::size_t n, Lobe::Evaluation* out); \
  }
PBRFIT_DECLARE_GGX_LOBE_BATCH(generic)
PBRFIT_DECLARE_GGX_LOBE_BATCH(avx2)
PBRFIT_DECLARE_GGX_LOBE_BATCH(avx512)
#undef PBRFIT_DECLARE_GGX_LOBE_BATCH

inline GgxLobeBatch ggx_lobe_batch(KernelSet set) {
  switch (set) {
#if defined(PBRFIT_X86_KERNELS)
    case KernelSet::avx512: return avx512::ggx_lobe_batch;
    case KernelSet::avx2: return avx2::ggx_lobe_batch;
#endif
    default: return generic::ggx_lobe_batch;
  }
}

}  // namespace pbrfit::brdf::detail
