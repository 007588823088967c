#pragma once
// Internal: the split-sum DFG integrand on the unit square, for one view cosine mu and alpha > 0.
//
// Coordinates. v = (sqrt(1 - mu^2), 0, mu); the half vector h has polar angle theta, azimuth phi.
// With tau = tan(theta) / alpha, u = tau^2 / (1 + tau^2) is the CDF in theta of D(h)(n.h), so
// D(h)(n.h) dw_h = du dphi / (2 pi). Using dw_l = 4 (v.h) dw_h and the mirror symmetry phi -> -phi,
//   integral over the upper hemisphere of f(l) (n.l) dw_l
//     = (1/pi) int_0^pi dphi int_0^u_max(phi) du  4 V(v,l) (n.l) (v.h) / (n.h)  x {1 - Fc, Fc},
// Fc = (1 - v.h)^5. The light is above the horizon iff theta < theta_max(phi), so the horizon is the
// edge u = u_max of the domain, never inside it.
//
// Radial variable y = asinh(tau), du = 2 sinh(y) / cosh^3(y) dy: the integrand is analytic at the pole
// (u itself has a sqrt(u) term there), and the GGX tail, which the u variable squeezes into a sliver of
// width ~alpha^2 below u_max, spreads over O(1) in y.
//
// Two quadratic maps keep features that sit on the domain edge resolvable, so that |Kronrod - Gauss|
// stays an honest error estimate (checked against tight reference integrals over the 128 x 128 table):
//  - horizon: near n.l = 0, V (n.l) behaves like n.l / (n.l + c) with c ~ min(alpha, mu), a pole just
//    beyond the edge; y = y_max (1 - (1 - s)^2) moves it out to a distance ~sqrt(c);
//  - grazing views: for small mu, y_max(phi) changes over a width ~mu around phi = pi/2 (at mu = 0 it
//    jumps there, which is why t = 1/2 is a tile edge); phi = pi/2 (1 -+ (1 - 2t)^2) on either side of
//    t = 1/2 widens that to ~sqrt(mu).
// Jacobian: the measure du dphi / pi becomes 2 y_max (1 - s) du/dy * 2 |1 - 2t| ds dt.
//
// Invariants: x = (t, s) in [0,1]^2; values are finite for every mu in [0, 1] and alpha > 0; samples
// beyond the horizon (only reachable by rounding) contribute 0; y_max is capped at max_radial, which
// drops a tail of relative size below e^-40 (only reached when mu * alpha < ~1e-17, e.g. mu = 0).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "dfg_line.hpp"
#include "pbrfit/integrate/gauss_kronrod.hpp"
#include "fixed_view_visibility.hpp"

namespace pbrfit::brdf {

inline constexpr double max_radial = 40.0;

// tan(theta_max) for a = sin(theta_v) cos(phi), b = mu: the light l = 2 (v.h) h - v has
// n.l = a sin(2 theta) + b cos(2 theta), positive iff theta < theta_max = (atan2(a, b) + pi/2) / 2, and
// tan(theta_max) = (r + a) / b = b / (r - a) with r = |(a, b)|; +inf when the whole quarter is lit.
inline double tan_horizon(double a, double b) {
  const double r = std::sqrt(a * a + b * b);
  if (a > 0.0) return b > 0.0 ? (r + a) / b : std::numeric_limits<double>::infinity();
  if (b == 0.0) return 0.0;  // grazing view, light azimuth behind: nothing above the horizon
  return b / (r - a);
}

inline double pow5(double x) {
  const double squared = x * x;
  return squared * squared * x;
}

template <SmithVisibility Convention>
class DfgIntegrand {
 public:
  DfgIntegrand(double n_dot_v, double alpha)
      : n_dot_v_(n_dot_v),
        sin_theta_v_(std::sqrt(std::max(0.0, 1.0 - n_dot_v * n_dot_v))),
        alpha_(alpha),
        visibility_(alpha, n_dot_v),
        line_kernel_(detail::dfg_line_kernel<Convention>(active_kernel_set())) {}

  // The integrand restricted to one azimuth; everything that depends on phi only is computed here.
  class AzimuthSlice {
   public:
    AzimuthSlice(const DfgIntegrand& integrand, double t) : integrand_(integrand) {
      const double from_middle = 1.0 - 2.0 * t;
      const double clustered = from_middle * std::abs(from_middle);  // (1 - 2t)^2, signed
      const double phi = 0.5 * std::numbers::pi * (1.0 - clustered);
      sin_theta_v_cos_phi_ = integrand.sin_theta_v_ * std::cos(phi);
      const double tau_max = tan_horizon(sin_theta_v_cos_phi_, integrand.n_dot_v_) / integrand.alpha_;
      y_max_ = std::min(std::asinh(tau_max), max_radial);
      slice_jacobian_ = 4.0 * std::abs(from_middle) * y_max_;
    }

    std::array<double, 2> operator()(const std::array<double, 2>& x) const {
      const DfgIntegrand& in = integrand_;
      const double to_horizon = 1.0 - x[1];
      const double y = (1.0 - to_horizon * to_horizon) * y_max_;
      const double exp_y = std::exp(y);
      const double exp_minus_y = 1.0 / exp_y;
      const double sinh_y = 0.5 * (exp_y - exp_minus_y);  // = tau; absolute error ~1e-16 near y = 0
      const double cosh_y = 0.5 * (exp_y + exp_minus_y);
      const double tan_theta = in.alpha_ * sinh_y;
      const double sec_theta = std::sqrt(1.0 + tan_theta * tan_theta);
      const double n_dot_h = 1.0 / sec_theta;
      const double sin_theta = tan_theta * n_dot_h;
      const double v_dot_h = sin_theta_v_cos_phi_ * sin_theta + in.n_dot_v_ * n_dot_h;
      const double n_dot_l = 2.0 * v_dot_h * n_dot_h - in.n_dot_v_;
      if (!(n_dot_l > 0.0)) return {0.0, 0.0};
      // 4 V (n.l) (v.h) / (n.h) * du/dy * dy/ds, with du/dy = 2 sinh(y) / cosh^3(y), as one division.
      const double numerator = 8.0 * in.visibility_.numerator() * n_dot_l * v_dot_h * sec_theta * sinh_y *
                               to_horizon * slice_jacobian_;
      const double weight = numerator / (in.visibility_.denominator(n_dot_l) * cosh_y * cosh_y * cosh_y);
      const double fresnel = pow5(1.0 - v_dot_h);
      return {weight * (1.0 - fresnel), weight * fresnel};
    }

    // The 15 points (t, s[i]) at once, as the tensor rule's line fast path (integrate/outer_binding.hpp):
    // out[2 i], out[2 i + 1] as operator() gives them, up to the vector exp's rounding (dfg_line.hpp).
    void line(const std::array<double, 2>& /*t is bound*/, const double* s, double* out) const {
      static_assert(detail::dfg_line_points == integrate::gauss_kronrod::kronrod_size);
      const DfgIntegrand& in = integrand_;
      const detail::DfgLine<Convention> line{in.visibility_, in.n_dot_v_, in.alpha_, sin_theta_v_cos_phi_, y_max_,
                                             slice_jacobian_};
      in.line_kernel_(line, s, out);
    }

   private:
    const DfgIntegrand& integrand_;
    double sin_theta_v_cos_phi_;
    double y_max_;           // asinh(tan(theta_max) / alpha), capped at max_radial
    double slice_jacobian_;  // the factors of the Jacobian that depend on t: 2 |1 - 2t| * 2 y_max
  };

  AzimuthSlice bind_outer(double t) const { return AzimuthSlice(*this, t); }

  std::array<double, 2> operator()(const std::array<double, 2>& x) const { return bind_outer(x[0])(x); }

 private:
  double n_dot_v_;
  double sin_theta_v_;
  double alpha_;
  FixedViewVisibility<Convention> visibility_;
  detail::DfgLineKernel<Convention> line_kernel_;  // of the process's kernel set
};

}  // namespace pbrfit::brdf
