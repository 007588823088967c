#include "pbrfit/ltc/descent_fit.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include "pbrfit/ltc/moment_matching.hpp"
#include "pbrfit/ltc/sliced_wasserstein.hpp"

namespace pbrfit::ltc {
namespace {

constexpr double step_growth = 1.3;
constexpr double step_shrink = 0.5;

bool usable(const Matrix3& m) { return m.allFinite() && std::abs(m.determinant()) > 1e-12; }

}  // namespace

AnisotropicFit fit_ltc_by_descent(std::span<const Vector3> targets, double amplitude, const Matrix3* warm_start,
                                  const DescentFitOptions& options) {
  SlicedWasserstein loss(targets, options.axes);
  AnisotropicFit fit;
  fit.amplitude = amplitude;
  // Candidate starts: the moment-matched LTC, the cosine itself (the SGD baseline's start) and the warm start;
  // the descent begins at the one with the lowest distance (the first on ties).
  std::vector<Matrix3> starts = {moment_matched_ltc(targets), Matrix3::Identity()};
  if (warm_start && usable(*warm_start)) starts.push_back(*warm_start);
  Matrix3 m = Matrix3::Identity(), gradient = Matrix3::Zero(), candidate_gradient;
  double value = std::numeric_limits<double>::infinity();
  for (const Matrix3& start : starts) {
    if (!usable(start)) continue;
    const Matrix3 candidate = start / start.norm();
    const double candidate_value = loss.gradient(candidate, candidate_gradient);
    ++fit.evaluations;
    if (candidate_value < value) {
      m = candidate;
      value = candidate_value;
      gradient = candidate_gradient;
    }
  }
  fit.start_distance = value;
  double step = options.initial_step;
  Matrix3 trial_gradient;
  for (std::size_t i = 0; i < options.iterations; ++i) {
    const Matrix3 trial = m - step * gradient;
    ++fit.evaluations;
    if (!usable(trial)) {
      step *= step_shrink;
      continue;
    }
    const double trial_value = loss.gradient(trial, trial_gradient);
    if (trial_value < value) {
      const double norm = trial.norm();
      m = trial / norm;
      gradient = trial_gradient * norm;  // d SW / dM at M / c is c times that at M
      value = trial_value;
      step *= step_growth;
    } else {
      step *= step_shrink;
    }
  }
  fit.matrix = m;
  fit.distance = value;
  fit.stop = optimize::StopReason::budget;
  return fit;
}

}  // namespace pbrfit::ltc
