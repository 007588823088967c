#include "pbrfit/ltc/isotropic_fit.hpp"

#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "pbrfit/ltc/distribution.hpp"
#include "pbrfit/ltc/isotropic_target.hpp"
#include "pbrfit/optimize/bounds.hpp"
#include "pbrfit/optimize/nelder_mead.hpp"

namespace pbrfit::ltc {
namespace {

const double min_log_scale = std::log(1e-6);
const double max_log_scale = std::log(8.0);
constexpr double max_skew = 4.0;

// The search point p: (ln m00, ln m11, m02, m20), or (ln m) for a rotationally symmetric lobe.
struct SearchSpace {
  bool symmetric = false;

  IsotropicParameters parameters(std::span<const double> p) const {
    if (symmetric) return {std::exp(p[0]), std::exp(p[0]), 0.0, 0.0};
    return {std::exp(p[0]), std::exp(p[1]), p[2], p[3]};
  }

  std::vector<double> point(const IsotropicParameters& start) const {
    const auto log_scale = [](double m) { return std::log(std::max(m, 1e-300)); };
    if (symmetric) return {log_scale(std::sqrt(start.m00 * start.m11))};
    return {log_scale(start.m00), log_scale(start.m11), start.m02, start.m20};
  }

  optimize::Bounds bounds() const {
    if (symmetric) return {{min_log_scale}, {max_log_scale}};
    return {{min_log_scale, min_log_scale, -max_skew, -max_skew}, {max_log_scale, max_log_scale, max_skew, max_skew}};
  }
};

}  // namespace

optimize::NelderMeadOptions default_cell_search() {
  optimize::NelderMeadOptions options;
  options.initial_step = 0.01;
  options.restart_step = 0.005;
  options.x_tolerance = 1e-4;
  options.f_tolerance_relative = 1e-5;
  options.max_restarts = 3;
  options.restart_gain_relative = 1e-4;
  return options;
}

CellFit fit_isotropic_cell(std::shared_ptr<const brdf::Lobe> lobe, const IsotropicParameters& start,
                           const CellFitOptions& options) {
  const IsotropicTarget target(std::move(lobe), {options.objective_points, options.moment_points, options.metric_points});
  CellFit fit;
  fit.moments = target.moments();
  const SearchSpace space{target.symmetric()};
  const optimize::Objective objective = [&](std::span<const double> p) { return target.objective(space.parameters(p)); };
  const optimize::Bounds bounds = space.bounds();
  std::vector<double> start_point = space.point(start);
  optimize::clamp_into(bounds, start_point);
  const optimize::NelderMeadResult search =
      optimize::nelder_mead(objective, bounds, start_point, options.search, options.max_evaluations);

  fit.parameters = space.parameters(search.best.x);
  fit.matrix = target.matrix(fit.parameters);
  fit.shader = shader_form(fit.matrix);
  fit.objective = search.best.value;
  fit.evaluations = search.evaluations;
  fit.stop = search.stop;
  fit.error = target.judge(fit.matrix);
  return fit;
}

}  // namespace pbrfit::ltc
