// The LTC batch kernels (ltc_batch.hpp) of one kernel set. Included once by each ltc_batch_isa_<set>.cpp,
// inside a namespace named by PBRFIT_KERNEL_ISA, so that the sets' copies never meet at link time.
#ifndef PBRFIT_KERNEL_ISA
#error "ltc_batch_kernels.hpp is included by the ltc_batch_isa_<set>.cpp files only"
#endif
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "ltc_batch.hpp"
#include "pbrfit/geometry/kernel_lanes.hpp"

namespace pbrfit::ltc::detail::PBRFIT_KERNEL_ISA {

namespace {

using kernel_lanes::Directions;
using kernel_lanes::gather;
using kernel_lanes::lanes;
using kernel_lanes::Lanes;
using kernel_lanes::square_root;

// The matrix m (row-major) times each direction, summed as Eigen 3.4 sums a 3 x 3 product on the generic
// target: rows 0 and 1 in a packet, (a + b) + c; row 2 by its unrolled reduction, a + (b + c).
Directions times(const double* m, const Directions& v) {
  return {m[0] * v.x + m[1] * v.y + m[2] * v.z, m[3] * v.x + m[4] * v.y + m[5] * v.z,
          m[6] * v.x + (m[7] * v.y + m[8] * v.z)};
}

void transform_group(const LtcConstants& ltc, const Vector3* base, std::size_t n, Vector3* direction, double* pdf) {
  const Directions s = gather(base, n);
  const Directions image = times(ltc.m, s);
  const Lanes length = square_root(image.x * image.x + image.y * image.y + image.z * image.z);
  const Lanes density = s.z * std::numbers::inv_pi * ltc.inverse_determinant * length * length * length;
  const Lanes x = image.x / length, y = image.y / length, z = image.z / length;
  for (std::size_t i = 0; i < n; ++i) {
    direction[i] = Vector3(x[i], y[i], z[i]);
    pdf[i] = density[i];
  }
}

void pdf_group(const LtcConstants& ltc, const Vector3* w, std::size_t n, double* pdf) {
  const Directions original = times(ltc.inverse, gather(w, n));
  const Lanes length_squared = original.x * original.x + original.y * original.y + original.z * original.z;
  const Lanes cosine = (original.z > 0.0).select(original.z, 0.0);  // std::max(0.0, z), -0 and NaN to +0
  const Lanes density = cosine * ltc.inverse_determinant * std::numbers::inv_pi / (length_squared * length_squared);
  for (std::size_t i = 0; i < n; ++i) pdf[i] = density[i];
}

}  // namespace

[[gnu::flatten]] void transform_many(const LtcConstants& ltc, const Vector3* base, std::size_t n, Vector3* direction,
                                     double* pdf) {
  for (std::size_t first = 0; first < n; first += lanes)
    transform_group(ltc, base + first, std::min(lanes, n - first), direction + first, pdf + first);
}

[[gnu::flatten]] void pdf_many(const LtcConstants& ltc, const Vector3* w, std::size_t n, double* pdf) {
  for (std::size_t first = 0; first < n; first += lanes) pdf_group(ltc, w + first, std::min(lanes, n - first), pdf + first);
}

}  // namespace pbrfit::ltc::detail::PBRFIT_KERNEL_ISA
