#pragma once
// What one cell of an isotropic LTC table is fitted to (Heitz et al. 2016, section 4): a lobe rho
// (brdf/lobe.hpp) for one view, its moments (lobe_moments.hpp: the albedo is the LTC's amplitude, the
// average direction orients the parametrization of isotropic_parameters.hpp), the fitting objective (the
// cubed error of fit_error.hpp on `objective_points` MIS points per strategy) and a judge of the result on a
// finer lattice (`metric_points`; none when 0). Every isotropic LTC table (GGX, the other BRDF families, a BRDF
// written as an expression, a measured material) is fitted through this one class.
//
// At normal view (cos theta_v = 1) the lobe is rotationally symmetric: the average direction is the normal and
// only m00 is free (m11 = m00, m02 = m20 = 0, whatever the parameters say).
//
// Invariants: immutable after construction; objective() and judge() are pure functions of their arguments;
// objective() is +inf where the lobe would lose its orientation (det M <= 0).
#include <cstddef>
#include <memory>
#include <optional>

#include "pbrfit/brdf/lobe.hpp"
#include "pbrfit/ltc/distribution.hpp"
#include "pbrfit/ltc/fit_error.hpp"
#include "pbrfit/ltc/isotropic_parameters.hpp"
#include "pbrfit/ltc/lobe_moments.hpp"

namespace pbrfit::ltc {

struct IsotropicTargetOptions {
  std::size_t objective_points = 512;  // per sampling strategy
  std::size_t moment_points = 4096;
  std::size_t metric_points = 4096;    // 0: no judge
};

class IsotropicTarget {
 public:
  IsotropicTarget(std::shared_ptr<const brdf::Lobe> lobe, const IsotropicTargetOptions& options);

  const brdf::Lobe& lobe() const { return *lobe_; }
  const std::shared_ptr<const brdf::Lobe>& shared_lobe() const { return lobe_; }
  bool symmetric() const { return lobe_->view().z() >= 1.0; }
  const LobeMoments& moments() const { return moments_; }

  Matrix3 matrix(const IsotropicParameters& parameters) const;
  LtcDistribution distribution(const Matrix3& m) const { return LtcDistribution(m, moments_.albedo); }
  double objective(const IsotropicParameters& parameters) const;
  // Both errors of M on the judge's lattice, amplitude the albedo; zero errors without a judge.
  FitError judge(const Matrix3& m) const;

 private:
  std::shared_ptr<const brdf::Lobe> lobe_;
  LobeMoments moments_;
  FitErrorEstimator objective_;
  std::optional<FitErrorEstimator> judge_;
};

}  // namespace pbrfit::ltc
