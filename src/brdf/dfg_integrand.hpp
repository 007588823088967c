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
// Horizon layer: near n.l = 0, V (n.l) behaves like n.l / (n.l + c) with c ~ min(alpha, mu), a pole just
// beyond the edge of the domain that can make |Kronrod - Gauss| underestimate the error of a tile
// touching the horizon. The map y = y_max (1 - (1 - s)^2) moves that pole out to a distance ~sqrt(c),
// which keeps the estimate honest (checked against tight reference integrals) for ~25% more samples.
// The unit square maps as phi = pi t and that y; the Jacobian pi dy/ds = 2 pi y_max (1 - s) leaves
// 2 y_max (1 - s) after the 1/pi.
//
// Invariants: x = (t, s) in [0,1]^2; values are finite for every mu in [0, 1] and alpha > 0; samples
// beyond the horizon (only reachable by rounding) contribute 0; y_max is capped at max_radial, which
// drops a tail of relative size below e^-40 (only reached when mu * alpha < ~1e-17, e.g. mu = 0).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

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
        visibility_(alpha, n_dot_v) {}

  // The integrand restricted to one azimuth; everything that depends on phi only is computed here.
  class AzimuthSlice {
   public:
    AzimuthSlice(const DfgIntegrand& integrand, double t) : integrand_(integrand) {
      sin_theta_v_cos_phi_ = integrand.sin_theta_v_ * std::cos(std::numbers::pi * t);
      const double tau_max = tan_horizon(sin_theta_v_cos_phi_, integrand.n_dot_v_) / integrand.alpha_;
      y_max_ = std::min(std::asinh(tau_max), max_radial);
    }

    std::array<double, 2> operator()(const std::array<double, 2>& x) const {
      const DfgIntegrand& in = integrand_;
      const double to_horizon = 1.0 - x[1];
      const double y = (1.0 - to_horizon * to_horizon) * y_max_;
      const double exp_minus_one = std::expm1(y);
      const double exp_minus_y = 1.0 / (1.0 + exp_minus_one);
      const double sinh_y = 0.5 * exp_minus_one * (1.0 + exp_minus_y);  // = tau, accurate at small y
      const double cosh_y = 0.5 * (1.0 + exp_minus_one + exp_minus_y);
      const double tan_theta = in.alpha_ * sinh_y;
      const double n_dot_h = 1.0 / std::sqrt(1.0 + tan_theta * tan_theta);
      const double sin_theta = tan_theta * n_dot_h;
      const double v_dot_h = sin_theta_v_cos_phi_ * sin_theta + in.n_dot_v_ * n_dot_h;
      const double n_dot_l = 2.0 * v_dot_h * n_dot_h - in.n_dot_v_;
      if (!(n_dot_l > 0.0)) return {0.0, 0.0};
      const double du_dy = 2.0 * sinh_y / (cosh_y * cosh_y * cosh_y);
      const double measure = du_dy * 2.0 * y_max_ * to_horizon;  // du/ds
      const double weight = 4.0 * in.visibility_.visibility(n_dot_l) * n_dot_l * v_dot_h / n_dot_h * measure;
      const double fresnel = pow5(1.0 - v_dot_h);
      return {weight * (1.0 - fresnel), weight * fresnel};
    }

   private:
    const DfgIntegrand& integrand_;
    double sin_theta_v_cos_phi_;
    double y_max_;  // asinh(tan(theta_max) / alpha), capped at max_radial
  };

  AzimuthSlice bind_outer(double t) const { return AzimuthSlice(*this, t); }

  std::array<double, 2> operator()(const std::array<double, 2>& x) const { return bind_outer(x[0])(x); }

 private:
  double n_dot_v_;
  double sin_theta_v_;
  double alpha_;
  FixedViewVisibility<Convention> visibility_;
};

}  // namespace pbrfit::brdf
