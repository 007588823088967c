#include "pbrfit/ltc/sphere_form_factor.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pbrfit::ltc {
namespace {

constexpr double half_pi = 0.5 * std::numbers::pi;

// The integral of max(0, cos theta) over a cap of radius sigma centred at polar angle omega that straddles
// the horizon (Snyder 1996): with gamma = asin(cos sigma / sin omega),
//   G = pi/2 - gamma + sin gamma cos gamma - 2 sin omega cos sigma cos gamma,
//   H = cos omega (cos gamma sqrt(sin^2 sigma - cos^2 gamma) + sin^2 sigma asin(cos gamma / sin sigma)),
// and the integral is pi cos omega sin^2 sigma + G - H above the horizon's pole side, G + H below it.
double straddling_cap_integral(double omega, double sigma) {
  const double sin_sigma = std::sin(sigma);
  const double sin_squared = sin_sigma * sin_sigma;
  const double gamma = std::asin(std::clamp(std::cos(sigma) / std::sin(omega), -1.0, 1.0));
  const double cos_gamma = std::cos(gamma);
  const double g = half_pi - gamma + std::sin(gamma) * cos_gamma - 2.0 * std::sin(omega) * std::cos(sigma) * cos_gamma;
  const double chord = std::sqrt(std::max(0.0, sin_squared - cos_gamma * cos_gamma));
  const double edge_angle = std::asin(std::min(1.0, cos_gamma / sin_sigma));
  const double h = std::cos(omega) * (cos_gamma * chord + sin_squared * edge_angle);
  if (omega < half_pi) return std::numbers::pi * std::cos(omega) * sin_squared + g - h;
  return g + h;
}

}  // namespace

double cap_form_factor(double cos_centre, double sin_squared_radius) {
  const double z = std::clamp(cos_centre, -1.0, 1.0);
  const double length = std::clamp(sin_squared_radius, 0.0, 1.0);
  if (length == 0.0) return 0.0;
  const double omega = std::acos(z);
  const double sigma = std::asin(std::sqrt(length));
  if (omega + sigma <= half_pi) return length * z;  // entirely above the horizon: |F| cos omega
  if (omega - sigma >= half_pi) return 0.0;
  return std::clamp(straddling_cap_integral(omega, sigma) * std::numbers::inv_pi, 0.0, 1.0);
}

double sphere_form_factor_ratio(double cos_centre, double length) {
  const double clamped_length = std::clamp(length, 0.0, 1.0);
  if (clamped_length == 0.0) return std::max(0.0, std::min(cos_centre, 1.0));
  return cap_form_factor(cos_centre, clamped_length) / clamped_length;
}

double horizon_clipped_form_factor(const Vector3& vector_form_factor) {
  const double length = vector_form_factor.norm();
  if (length == 0.0) return 0.0;
  const double clamped_length = std::min(length, 1.0);
  return clamped_length * sphere_form_factor_ratio(vector_form_factor.z() / length, clamped_length);
}

}  // namespace pbrfit::ltc
