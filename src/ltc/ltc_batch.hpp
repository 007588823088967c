#pragma once
// Internal: LtcDistribution::transform and pdf over many directions, as vector code in each kernel set
// (core/kernel_set.hpp).
//
// Contract: bit for bit the scalar members in every set. The kernels repeat their operations in order
// (a 3 x 3 product summed as Eigen's is, ltc_batch_kernels.hpp; |v| as sqrt((x^2 + y^2) + z^2)); arithmetic
// and sqrt round the same in every set (no contraction into FMA). A unit test holds the kernels to the
// scalar members, so an Eigen that sums differently is caught, not silently followed.
// Directions go 16 at a time, the last group padded with copies.
#include <cstddef>

#include "pbrfit/core/kernel_set.hpp"
#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::ltc::detail {

struct LtcConstants {
  double m[9];          // M, row-major
  double inverse[9];    // M^-1, row-major
  double inverse_determinant;  // |det M^-1|
};

struct LtcBatch {
  // direction[i] = normalize(M base[i]), pdf[i] = D / amplitude there (LtcDistribution::transform).
  void (*transform)(const LtcConstants& ltc, const Vector3* base, std::size_t n, Vector3* direction, double* pdf);
  // pdf[i] = LtcDistribution::pdf(w[i]).
  void (*pdf)(const LtcConstants& ltc, const Vector3* w, std::size_t n, double* pdf);
};

#define PBRFIT_DECLARE_LTC_BATCH(set)                                                                       \
  namespace set {                                                                                         \
  void transform_many(const LtcConstants& ltc, const Vector3* base, std::size_t n, Vector3* direction,    \
                      double* pdf);                                                                       \
  void pdf_many(const LtcConstants& ltc, const Vector3* w, std::size_t n, double* pdf);                   \
  }
PBRFIT_DECLARE_LTC_BATCH(generic)
PBRFIT_DECLARE_LTC_BATCH(avx2)
PBRFIT_DECLARE_LTC_BATCH(avx512)
#undef PBRFIT_DECLARE_LTC_BATCH

inline LtcBatch ltc_batch(KernelSet set) {
  switch (set) {
#if defined(PBRFIT_X86_KERNELS)
    case KernelSet::avx512: return {avx512::transform_many, avx512::pdf_many};
    case KernelSet::avx2: return {avx2::transform_many, avx2::pdf_many};
#endif
    default: return {generic::transform_many, generic::pdf_many};
  }
}

}  // namespace pbrfit::ltc::detail
