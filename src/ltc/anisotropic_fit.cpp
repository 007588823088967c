#include "pbrfit/ltc/anisotropic_fit.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include "pbrfit/ltc/moment_matching.hpp"
#include "pbrfit/ltc/sliced_wasserstein.hpp"
#include "pbrfit/optimize/bounds.hpp"
#include "pbrfit/optimize/nelder_mead.hpp"

namespace pbrfit::ltc {
namespace {

constexpr std::size_t free_entries = 8;
constexpr double max_correction = 3.0;
constexpr double min_correction_determinant = 1e-6;

// I + P for the search point p: the entries of P row by row, P22 = 0.
Matrix3 correction(std::span<const double> p) {
  Matrix3 c;
  c << 1.0 + p[0], p[1], p[2],  //
      p[3], 1.0 + p[4], p[5],   //
      p[6], p[7], 1.0;
  return c;
}

}  // namespace

optimize::NelderMeadOptions default_anisotropic_search() {
  optimize::NelderMeadOptions options;
  options.initial_step = 0.02;
  options.restart_step = 0.01;
  options.x_tolerance = 1e-4;
  options.f_tolerance_relative = 1e-6;
  options.max_restarts = 4;
  options.restart_gain_relative = 1e-4;
  return options;
}

namespace {

AnisotropicFit search_from(SlicedWasserstein& loss, const Matrix3& start, double amplitude,
                           const AnisotropicFitOptions& options) {
  const optimize::Objective objective = [&](std::span<const double> p) {
    const Matrix3 c = correction(p);
    if (std::abs(c.determinant()) < min_correction_determinant) return std::numeric_limits<double>::infinity();
    return loss.distance(start * c);
  };
  const optimize::Bounds bounds = optimize::uniform_bounds(free_entries, -max_correction, max_correction);
  const std::vector<double> origin(free_entries, 0.0);
  const optimize::NelderMeadResult search =
      optimize::nelder_mead(objective, bounds, origin, options.search, options.max_evaluations);

  AnisotropicFit fit;
  fit.matrix = start * correction(search.best.x);
  fit.amplitude = amplitude;
  fit.distance = search.best.value;
  fit.start_distance = loss.distance(start);
  fit.evaluations = search.evaluations;
  fit.stop = search.stop;
  return fit;
}

}  // namespace

AnisotropicFit fit_ltc_to_samples(std::span<const Vector3> targets, double amplitude,
                                  const AnisotropicFitOptions& options) {
  SlicedWasserstein loss(targets, options.axes);
  return search_from(loss, moment_matched_ltc(targets), amplitude, options);
}

AnisotropicFit fit_ltc_to_samples(std::span<const Vector3> targets, double amplitude, const Matrix3& warm_start,
                                  const AnisotropicFitOptions& options) {
  SlicedWasserstein loss(targets, options.axes);
  const Matrix3 matched = moment_matched_ltc(targets);
  const bool warm_usable = warm_start.allFinite() && std::abs(warm_start.determinant()) > 1e-12;
  const bool warm_better = warm_usable && loss.distance(warm_start) < loss.distance(matched);
  return search_from(loss, warm_better ? warm_start : matched, amplitude, options);
}

}  // namespace pbrfit::ltc
