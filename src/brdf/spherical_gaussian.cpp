#include "pbrfit/brdf/spherical_gaussian.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pbrfit::brdf {
namespace {

// (1 - exp(-2 lambda)) / lambda, the integral of exp(-lambda (1 - cos)) over cos in [-1, 1].
double unit_zonal_integral(double lambda) { return -std::expm1(-2.0 * lambda) / lambda; }

}  // namespace

double SphericalGaussian::value(const Vector3& w) const {
  return amplitude * std::exp(-sharpness * (1.0 - w.dot(axis)));
}

double SphericalGaussian::integral() const { return amplitude * 2.0 * std::numbers::pi * unit_zonal_integral(sharpness); }

double SphericalGaussian::pdf(const Vector3& w) const {
  return std::exp(-sharpness * (1.0 - w.dot(axis))) / (2.0 * std::numbers::pi * unit_zonal_integral(sharpness));
}

Vector3 SphericalGaussian::sample(double u1, double u2) const {
  // 1 - cos theta = -log(1 - (1 - e^{-2 lambda}) u1) / lambda = -log1p(expm1(-2 lambda) u1) / lambda.
  const double one_minus_cos = std::clamp(-std::log1p(std::expm1(-2.0 * sharpness) * u1) / sharpness, 0.0, 2.0);
  const double cos_theta = 1.0 - one_minus_cos;
  const double sin_theta = std::sqrt(std::max(0.0, one_minus_cos * (2.0 - one_minus_cos)));
  const double phi = 2.0 * std::numbers::pi * u2;
  const Frame frame = Frame::from_z(axis);
  return frame.from_local(Vector3(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta));
}

}  // namespace pbrfit::brdf
