#include "pbrfit/brdf/sh_projection.hpp"

#include "pbrfit/integrate/direction_domain.hpp"

namespace pbrfit::brdf {

ShProjection project_to_sh(const std::function<double(const Vector3&)>& f, double z_min,
                           const integrate::AdaptiveOptions& options) {
  const auto weighted_basis = [&f](const integrate::UnitDirection& d) {
    const Vector3 w(d[0], d[1], d[2]);
    const double value = f(w);
    ShCoefficients terms = sh_basis(w);
    for (double& term : terms) term *= value;
    return terms;
  };
  const auto result = integrate::integrate_over_directions<9>(weighted_basis, z_min, 1.0, 4, options);
  ShProjection projection;
  projection.sh = result.value;
  projection.error_estimate = result.error_estimate;
  projection.evaluations = result.evaluations;
  projection.converged = result.converged;
  return projection;
}

}  // namespace pbrfit::brdf
