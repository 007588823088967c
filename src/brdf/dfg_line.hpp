#pragma once
// Internal: the split-sum DFG integrand (dfg_integrand.hpp) along one line of the Gauss-Kronrod grid, the
// azimuth fixed and the 15 radial nodes at once, as vector code in each kernel set (core/kernel_set.hpp).
//
// Contract: dfg_line_kernel<C>(set)(line, s, out) writes, for i = 0..14, the integrand at radial
// coordinate s[i] as out[2 i] (the 1 - Fc part) and out[2 i + 1] (the Fc part). Arithmetic and sqrt
// round as in AzimuthSlice::operator(), term for term; exp is Eigen's vector exp, which may differ from
// std::exp, and between sets, by a few ulps. A value depends on its s alone: all 15 nodes (and a copy of
// the last in the 16th lane) take the same packet code.
#include "fixed_view_visibility.hpp"
#include "pbrfit/core/kernel_set.hpp"

namespace pbrfit::brdf::detail {

inline constexpr int dfg_line_points = 15;

// Everything an azimuth slice fixes.
template <SmithVisibility Convention>
struct DfgLine {
  FixedViewVisibility<Convention> visibility;
  double n_dot_v;
  double alpha;
  double sin_theta_v_cos_phi;
  double y_max;
  double slice_jacobian;
};

template <SmithVisibility Convention>
using DfgLineKernel = void (*)(const DfgLine<Convention>& line, const double* s, double* out);

#define PBRFIT_DECLARE_DFG_LINES(set)                                                                 \
  namespace set {                                                                                     \
  void dfg_line_height_correlated(const DfgLine<SmithVisibility::height_correlated>& line,           \
                                  const double* s, double* out);                                     \
  void dfg_line_separable(const DfgLine<SmithVisibility::separable>& line, const double* s, double* out); \
  void dfg_line_separable_schlick(const DfgLine<SmithVisibility::separable_schlick>& line, const double* s, \
                                  double* out);                                                      \
  }
PBRFIT_DECLARE_DFG_LINES(generic)
PBRFIT_DECLARE_DFG_LINES(avx2)
PBRFIT_DECLARE_DFG_LINES(avx512)
#undef PBRFIT_DECLARE_DFG_LINES

#define PBRFIT_DFG_LINE_OF(set)                                                                        \
  if constexpr (Convention == SmithVisibility::height_correlated) return set::dfg_line_height_correlated; \
  else if constexpr (Convention == SmithVisibility::separable) return set::dfg_line_separable;          \
  else return set::dfg_line_separable_schlick

template <SmithVisibility Convention>
DfgLineKernel<Convention> dfg_line_kernel(KernelSet set) {
  switch (set) {
#if defined(PBRFIT_X86_KERNELS)
    case KernelSet::avx512: PBRFIT_DFG_LINE_OF(avx512);
    case KernelSet::avx2: PBRFIT_DFG_LINE_OF(avx2);
#endif
    default: PBRFIT_DFG_LINE_OF(generic);
  }
}
#undef PBRFIT_DFG_LINE_OF

}  // namespace pbrfit::brdf::detail
