#include "pbrfit/brdf/disney_diffuse_lobe.hpp"

#include <cmath>
#include <stdexcept>

#include "pbrfit/brdf/disney_diffuse.hpp"
#include "pbrfit/brdf/sh_projection.hpp"

namespace pbrfit::brdf {
namespace {

Vector3 view_in_xz(double n_dot_v) { return {std::sqrt(std::max(0.0, 1.0 - n_dot_v * n_dot_v)), 0.0, n_dot_v}; }

}  // namespace

double blend_factor_beta(const Vector3& direction, double n_dot_v) {
  const double sin_v = std::sqrt(std::max(0.0, 1.0 - n_dot_v * n_dot_v));
  const double denominator = sin_v * direction.z() + direction.x() * (1.0 - n_dot_v);
  if (sin_v == 0.0 || denominator == 0.0) return 0.0;
  return direction.x() / denominator;
}

Vector3 blended_direction(double beta, double n_dot_v) {
  const Vector3 blend = (1.0 - beta) * Vector3::UnitZ() + beta * view_in_xz(n_dot_v);
  const double length = blend.norm();
  return length > 0.0 ? Vector3(blend / length) : Vector3::UnitZ();
}

DisneyDiffuseLobe disney_diffuse_lobe(double roughness, double n_dot_v, const integrate::AdaptiveOptions& options) {
  if (!(roughness >= 0.0 && roughness <= 1.0)) throw std::invalid_argument("disney_diffuse_lobe: roughness outside [0, 1]");
  if (!(n_dot_v >= 0.0 && n_dot_v <= 1.0)) throw std::invalid_argument("disney_diffuse_lobe: n.v outside [0, 1]");
  const Vector3 view = view_in_xz(n_dot_v);
  const ShProjection projection =
      project_to_sh([&](const Vector3& l) { return disney_diffuse_cbrdf(roughness, view, l); }, 0.0, options);
  DisneyDiffuseLobe lobe;
  lobe.sh = projection.sh;
  lobe.direction = optimal_linear_direction(projection.sh);
  lobe.beta = blend_factor_beta(lobe.direction, n_dot_v);
  lobe.zh = zonal_coefficients(projection.sh, lobe.direction);
  lobe.error_estimate = projection.error_estimate;
  lobe.evaluations = projection.evaluations;
  lobe.converged = projection.converged;
  return lobe;
}

}  // namespace pbrfit::brdf
