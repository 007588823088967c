#include "pbrfit/ltc/isotropic_target.hpp"

#include <limits>
#include <stdexcept>

namespace pbrfit::ltc {
namespace {

std::shared_ptr<const brdf::Lobe> checked(std::shared_ptr<const brdf::Lobe> lobe) {
  if (!lobe) throw std::invalid_argument("ltc: an isotropic target needs a lobe");
  return lobe;
}

}  // namespace

IsotropicTarget::IsotropicTarget(std::shared_ptr<const brdf::Lobe> lobe, const IsotropicTargetOptions& options)
    : lobe_(checked(std::move(lobe))), objective_(lobe_, options.objective_points) {
  // The moments and the judge sum over the same lattice's samples when their sizes agree (the defaults):
  // the lobe is sampled and evaluated once for both.
  LobeSamples samples = sample_lobe(*lobe_, options.moment_points);
  moments_ = measure_moments(*lobe_, samples);
  if (symmetric()) moments_.average_direction = Vector3::UnitZ();
  if (options.metric_points == options.moment_points && options.metric_points > 0) {
    judge_.emplace(lobe_, std::move(samples));
  } else if (options.metric_points > 0) {
    judge_.emplace(lobe_, options.metric_points);
  }
}

Matrix3 IsotropicTarget::matrix(const IsotropicParameters& p) const {
  const IsotropicParameters used = symmetric() ? IsotropicParameters{p.m00, p.m00, 0.0, 0.0} : p;
  return isotropic_ltc_matrix(used, moments_.average_direction);
}

double IsotropicTarget::objective(const IsotropicParameters& p) const {
  const double det = symmetric() ? p.m00 : p.m00 - p.m02 * p.m20;
  if (!(det > 1e-300)) return std::numeric_limits<double>::infinity();  // the lobe must keep its orientation
  return objective_.cubed_error(distribution(matrix(p)));
}

FitError IsotropicTarget::judge(const Matrix3& m) const { return judge_ ? judge_->errors(distribution(m)) : FitError{}; }

}  // namespace pbrfit::ltc
