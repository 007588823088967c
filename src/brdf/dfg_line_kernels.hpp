// The DFG line kernel (dfg_line.hpp) of one kernel set. Included once by each dfg_line_isa_<set>.cpp,
// inside a namespace named by PBRFIT_KERNEL_ISA, so that the sets' copies never meet at link time.
#ifndef PBRFIT_KERNEL_ISA
#error "dfg_line_kernels.hpp is included by the dfg_line_isa_<set>.cpp files only"
#endif
#include <Eigen/Core>
#include <cmath>

#include "dfg_line.hpp"
#include "pbrfit/geometry/kernel_lanes.hpp"

namespace pbrfit::brdf::detail::PBRFIT_KERNEL_ISA {

namespace {

using kernel_lanes::Lanes;
using kernel_lanes::square_root;

// The visibility's denominator, FixedViewVisibility::denominator over lanes (the same terms in the same order).
template <SmithVisibility Convention>
Lanes denominator(const DfgLine<Convention>& line, const Lanes& n_dot_l) {
  const FixedViewVisibility<Convention>& v = line.visibility;
  if constexpr (Convention == SmithVisibility::height_correlated) {
    const Lanes width = square_root(n_dot_l * n_dot_l * (1.0 - v.alpha_squared()) + v.alpha_squared());
    return n_dot_l * v.view_term() + line.n_dot_v * width;
  } else if constexpr (Convention == SmithVisibility::separable) {
    const Lanes width = square_root(n_dot_l * n_dot_l * (1.0 - v.alpha_squared()) + v.alpha_squared());
    return (line.n_dot_v + v.view_term()) * (n_dot_l + width);
  } else {
    return v.view_term() * (n_dot_l * (1.0 - v.k()) + v.k());
  }
}

// AzimuthSlice::operator() of dfg_integrand.hpp over 16 lanes; see there for the variables.
template <SmithVisibility Convention>
void evaluate(const DfgLine<Convention>& line, const double* s, double* out) {
  Lanes radial;
  for (int i = 0; i < dfg_line_points; ++i) radial[i] = s[i];
  radial[15] = s[dfg_line_points - 1];  // the 16th lane repeats the last node
  const Lanes to_horizon = 1.0 - radial;
  const Lanes y = (1.0 - to_horizon * to_horizon) * line.y_max;
  const Lanes exp_y = y.exp();
  const Lanes exp_minus_y = exp_y.inverse();
  const Lanes sinh_y = 0.5 * (exp_y - exp_minus_y);
  const Lanes cosh_y = 0.5 * (exp_y + exp_minus_y);
  const Lanes tan_theta = line.alpha * sinh_y;
  const Lanes sec_theta = square_root(1.0 + tan_theta * tan_theta);
  const Lanes n_dot_h = sec_theta.inverse();
  const Lanes sin_theta = tan_theta * n_dot_h;
  const Lanes v_dot_h = line.sin_theta_v_cos_phi * sin_theta + line.n_dot_v * n_dot_h;
  const Lanes n_dot_l = 2.0 * v_dot_h * n_dot_h - line.n_dot_v;
  const Lanes numerator = 8.0 * line.visibility.numerator() * n_dot_l * v_dot_h * sec_theta * sinh_y *
                          to_horizon * line.slice_jacobian;
  const Lanes weight = numerator / (denominator(line, n_dot_l) * cosh_y * cosh_y * cosh_y);
  const Lanes from_fresnel = 1.0 - v_dot_h;
  const Lanes squared = from_fresnel * from_fresnel;
  const Lanes fresnel = squared * squared * from_fresnel;
  const Lanes lit = (n_dot_l > 0.0).select(weight, 0.0);  // also 0 where n.l is NaN, as the scalar code
  const Lanes specular = lit * (1.0 - fresnel);
  const Lanes edge = lit * fresnel;
  for (int i = 0; i < dfg_line_points; ++i) {
    out[2 * i] = specular[i];
    out[2 * i + 1] = edge[i];
  }
}

}  // namespace

[[gnu::flatten]] void dfg_line_height_correlated(const DfgLine<SmithVisibility::height_correlated>& line,
                                                 const double* s, double* out) {
  evaluate(line, s, out);
}

[[gnu::flatten]] void dfg_line_separable(const DfgLine<SmithVisibility::separable>& line, const double* s,
                                         double* out) {
  evaluate(line, s, out);
}

[[gnu::flatten]] void dfg_line_separable_schlick(const DfgLine<SmithVisibility::separable_schlick>& line,
                                                 const double* s, double* out) {
  evaluate(line, s, out);
}

}  // namespace pbrfit::brdf::detail::PBRFIT_KERNEL_ISA
