// The GGX lobe batch kernel (ggx_lobe_batch.hpp) of one kernel set. Included once by each
// ggx_lobe_batch_isa_<set>.cpp, inside a namespace named by PBRFIT_KERNEL_ISA, so that the sets' copies
// never meet at link time.
#ifndef PBRFIT_KERNEL_ISA
#error "ggx_lobe_batch_kernels.hpp is included by the ggx_lobe_batch_isa_<set>.cpp files only"
#endif
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "ggx_lobe_batch.hpp"
#include "pbrfit/geometry/kernel_lanes.hpp"

namespace pbrfit::brdf::detail::PBRFIT_KERNEL_ISA {

namespace {

using kernel_lanes::gather;
using kernel_lanes::lanes;
using kernel_lanes::Lanes;
using kernel_lanes::square_root;

// Up to 16 directions; lanes past n repeat the last direction and are not stored.
void evaluate_group(const GgxLobeConstants& lobe, const Vector3* l, std::size_t n, Lobe::Evaluation* out) {
  const auto [x, y, z] = gather(l, n);
  const double infinity = std::numeric_limits<double>::infinity();
  const double alpha_squared = lobe.alpha * lobe.alpha;
  // h = normalize(v + l); D(n.h) as ggx_distribution().
  const Lanes sum_x = lobe.view_x + x;
  const Lanes sum_y = lobe.view_y + y;
  const Lanes sum_z = lobe.view_z + z;
  const Lanes length = square_root(sum_x * sum_x + sum_y * sum_y + sum_z * sum_z);
  const Lanes n_dot_h = sum_z / length;
  const Lanes denominator = n_dot_h * n_dot_h * (alpha_squared - 1.0) + 1.0;
  const Lanes peak_free = alpha_squared / (std::numbers::pi * denominator * denominator);
  const Lanes distribution = (n_dot_h < 0.0).select(0.0, (denominator <= 0.0).select(infinity, peak_free));
  const Lanes scale = distribution / (4.0 * lobe.view_z);
  // Lambda(l) as ggx_smith_lambda() where l.z > 0 (alpha > 0).
  const Lanes cos_squared = z * z;
  const Lanes alpha_tan_squared = lobe.alpha * lobe.alpha * (1.0 - cos_squared) / cos_squared;
  const Lanes lambda = alpha_tan_squared / (2.0 * (1.0 + square_root(1.0 + alpha_tan_squared)));
  const Lanes value = scale / (1.0 + lobe.view_lambda + lambda);
  const Lanes pdf = lobe.masking * scale;
  const auto degenerate = length == 0.0;  // l = -v
  const Lanes kept_value = (degenerate || !(z > 0.0)).select(0.0, value);
  const Lanes kept_pdf = degenerate.select(0.0, pdf);
  for (std::size_t i = 0; i < n; ++i) out[i] = {kept_value[i], kept_pdf[i]};
}

}  // namespace

[[gnu::flatten]] void ggx_lobe_batch(const GgxLobeConstants& lobe, const Vector3* l, std::size_t n,
                                     Lobe::Evaluation* out) {
  for (std::size_t first = 0; first < n; first += lanes)
    evaluate_group(lobe, l + first, std::min(lanes, n - first), out + first);
}

}  // namespace pbrfit::brdf::detail::PBRFIT_KERNEL_ISA
