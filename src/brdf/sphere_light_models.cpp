#include "pbrfit/brdf/sphere_light_models.hpp"

#include <algorithm>
#include <cmath>

#include "pbrfit/brdf/ggx_lobe.hpp"

namespace pbrfit::brdf {

double soft_minimum(double x, double y, double s) {
  if (!(x > 0.0) || !(y > 0.0)) return 0.0;
  if (std::isinf(x)) return y;
  if (std::isinf(y)) return x;
  // Factor out the smaller value so that x^s does not overflow for tiny x and strongly negative s.
  const double smaller = std::min(x, y);
  const double larger = std::max(x, y);
  return smaller * std::pow(1.0 + std::pow(larger / smaller, s), 1.0 / s);
}

double roughness_modification_model(double alpha_modified, const SphereLight& light, const Vector3& view) {
  return ggx_cosine_weighted(alpha_modified, view, light.centre);
}

double capped_roughness_model(double alpha_modified, double cap, double smoothness, const SphereLight& light,
                              const Vector3& view) {
  return soft_minimum(roughness_modification_model(alpha_modified, light, view), cap, smoothness);
}

Vector3 representative_direction(const SphereLight& light, const Vector3& view, double smoothness) {
  const Vector3 reflected = mirror_about_normal(view);  // reflect(-v, n) for n = +z
  const Vector3 centre_to_ray = light.centre.dot(reflected) * reflected - light.centre;
  const double distance = centre_to_ray.norm();
  if (distance == 0.0) return light.centre;
  const double reach = light.radius() / distance;
  const double fraction = smoothness == 0.0 ? std::clamp(reach, 0.0, 1.0) : soft_minimum(1.0, reach, smoothness);
  return (light.centre + fraction * centre_to_ray).normalized();
}

double karis_sphere_normalization(double alpha, const SphereLight& light) {
  const double widened = std::min(1.0, alpha + light.radius() / 3.0);
  const double ratio = alpha / widened;
  return ratio * ratio;
}

double representative_point_model(double alpha_modified, double scale, const SphereLight& light,
                                  const Vector3& view) {
  return scale * ggx_cosine_weighted(alpha_modified, view, representative_direction(light, view, 0.0));
}

double smoothed_representative_point_model(double alpha_modified, double scale, double smoothness,
                                           const SphereLight& light, const Vector3& view) {
  return scale * ggx_cosine_weighted(alpha_modified, view, representative_direction(light, view, smoothness));
}

double course_smoothed_normalization(double alpha, const SphereLight& light) {
  constexpr double a = 0.962406, b = 0.375892, c = 0.962406;
  return 1.0 / (a + b * std::tan(light.half_angle) / std::pow(alpha, c));
}

}  // namespace pbrfit::brdf
