#include "pbrfit/brdf/cloth_albedo.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "dfg_integrand.hpp"
#include "pbrfit/brdf/sheen.hpp"

namespace pbrfit::brdf {
namespace {

// x = (t, s) in [0, 1]^2: phi = pi/2 (1 -+ (1 - 2t)^2) on either side of t = 1/2 (the grazing view's horizon
// jump), theta = theta_max(phi) (1 - (1 - s)^2). The measure 2 dphi sin(theta) dtheta (both azimuth halves)
// of the half vector, times dw_l / dw_h = 4 (v.h).
class ClothIntegrand {
 public:
  ClothIntegrand(double n_dot_v, double alpha)
      : mu_(n_dot_v), sin_v_(std::sqrt(std::max(0.0, 1.0 - n_dot_v * n_dot_v))), alpha_(alpha) {}

  std::array<double, 1> operator()(const std::array<double, 2>& x) const {
    const double from_middle = 1.0 - 2.0 * x[0];
    const double phi = 0.5 * std::numbers::pi * (1.0 - from_middle * std::abs(from_middle));
    const double a = sin_v_ * std::cos(phi);
    const double theta_max = std::atan(tan_horizon(a, mu_));
    const double to_edge = 1.0 - x[1];
    const double theta = theta_max * (1.0 - to_edge * to_edge);
    const double n_dot_h = std::cos(theta), sin_theta = std::sin(theta);
    const double v_dot_h = a * sin_theta + mu_ * n_dot_h;
    const double n_dot_l = 2.0 * v_dot_h * n_dot_h - mu_;
    if (!(n_dot_l > 0.0) || !(v_dot_h > 0.0)) return {0.0};
    // dphi/dt = 2 pi |1 - 2t|, dtheta/ds = 2 theta_max (1 - s); both azimuth halves: factor 2.
    const double jacobian = 4.0 * std::numbers::pi * std::abs(from_middle) * 2.0 * theta_max * to_edge * sin_theta;
    const double value = charlie_distribution(alpha_, n_dot_h) * neubelt_visibility(mu_, n_dot_l) * n_dot_l;
    return {value * 4.0 * v_dot_h * jacobian};
  }

 private:
  double mu_, sin_v_, alpha_;
};

// Initial tiles: both azimuth halves, and the last tenth of the way to the horizon on its own.
constexpr std::array<integrate::Box<2>, 4> initial_tiles = {
    integrate::Box<2>{{0.0, 0.0}, {0.5, 0.9}}, integrate::Box<2>{{0.5, 0.0}, {1.0, 0.9}},
    integrate::Box<2>{{0.0, 0.9}, {0.5, 1.0}}, integrate::Box<2>{{0.5, 0.9}, {1.0, 1.0}}};

}  // namespace

ClothAlbedo integrate_cloth_albedo(double n_dot_v, double alpha, const integrate::AdaptiveOptions& options) {
  if (!(n_dot_v >= 0.0 && n_dot_v <= 1.0)) throw std::invalid_argument("cloth albedo: n_dot_v outside [0, 1]");
  if (!(alpha >= 0.0 && std::isfinite(alpha))) throw std::invalid_argument("cloth albedo: alpha must be >= 0");
  if (alpha == 0.0) return {0.0, 0.0, 0, true};
  const auto result = integrate::integrate_adaptive<2, 1>(ClothIntegrand(n_dot_v, alpha),
                                                          std::span<const integrate::Box<2>>(initial_tiles), options);
  return {result.value[0], result.error_estimate, result.evaluations, result.converged};
}

}  // namespace pbrfit::brdf
