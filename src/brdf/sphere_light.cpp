#include "pbrfit/brdf/sphere_light.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "pbrfit/brdf/ggx_lobe.hpp"
#include "pbrfit/integrate/direction_domain.hpp"

namespace pbrfit::brdf {

double SphereLight::radius() const { return std::sin(half_angle); }

SphereLight sphere_light_at(double incidence, double half_angle) {
  return SphereLight{Vector3(std::sin(incidence), 0.0, std::cos(incidence)), half_angle};
}

SphereLightResponse sphere_light_response(double alpha, const SphereLight& light, const Vector3& view,
                                          const integrate::AdaptiveOptions& options) {
  if (!(alpha > 0.0) || !std::isfinite(alpha)) throw std::invalid_argument("sphere light: alpha must be > 0");
  if (!(light.half_angle > 0.0 && light.half_angle <= 0.5 * std::numbers::pi)) {
    throw std::invalid_argument("sphere light: half-angle outside (0, pi/2]");
  }
  if (!(std::abs(light.centre.norm() - 1.0) < 1e-9)) throw std::invalid_argument("sphere light: centre not unit");
  const Frame frame = Frame::from_z(light.centre);
  const double cos_gamma = std::cos(light.half_angle);
  const double inverse_solid_angle = 1.0 / (2.0 * std::numbers::pi * (1.0 - cos_gamma));
  const auto integrand = [&](const integrate::UnitDirection& local) {
    const Vector3 l = frame.from_local(Vector3(local[0], local[1], local[2]));
    return std::array<double, 1>{ggx_cosine_weighted(alpha, view, l) * inverse_solid_angle};
  };
  const auto result = integrate::integrate_over_directions<1>(integrand, cos_gamma, 1.0, 2, options);
  return {result.value[0], result.error_estimate, result.evaluations, result.converged};
}

}  // namespace pbrfit::brdf
