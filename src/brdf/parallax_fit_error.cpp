#include "pbrfit/brdf/parallax_fit_error.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "pbrfit/brdf/projected_lobe.hpp"

namespace pbrfit::brdf {
namespace {

// Breakpoints 0, w/64, w/16, w/4, w: lobes peak at the centre, so tiles start small there.
std::vector<double> graded_breakpoints(double window) {
  return {0.0, window / 64.0, window / 16.0, window / 4.0, window};
}

// The integral times `factor` (2 pi r for the radial study, 2 for the half window of the angle study).
ProjectionError from_result(const integrate::AdaptiveResult<1>& result, double factor) {
  return {factor * result.value[0], factor * result.error_estimate, result.evaluations, result.converged};
}

}  // namespace

ProjectionError distance_fit_error(double alpha, double distance, const PerpendicularCandidate& candidate,
                                   double window, const integrate::AdaptiveOptions& options) {
  const ProjectedLobe source = perpendicular_lobe(alpha, distance);
  const ProjectedLobe fitted = perpendicular_lobe(candidate.alpha, 1.0);
  const auto integrand = [&](const std::array<double, 1>& r) {
    const double difference =
        source.density(r[0], 0.0) - (candidate.scale * fitted.density(r[0], 0.0) + candidate.offset);
    return std::array<double, 1>{r[0] * difference * difference};
  };
  const std::vector<double> edges = graded_breakpoints(window);
  std::vector<integrate::Box<1>> tiles;
  for (std::size_t i = 0; i + 1 < edges.size(); ++i) tiles.push_back({{edges[i]}, {edges[i + 1]}});
  const auto result = integrate::integrate_adaptive<1, 1>(integrand, std::span<const integrate::Box<1>>(tiles), options);
  return from_result(result, 2.0 * std::numbers::pi);
}

ProjectionError angle_fit_error(double alpha, double angle, double distance, const PerpendicularCandidate& candidate,
                                double window, const integrate::AdaptiveOptions& options) {
  const ProjectedLobe source = tilted_lobe(alpha, angle, distance);
  const ProjectedLobe fitted = perpendicular_lobe(candidate.alpha, distance, -candidate.shift * distance * std::sin(angle));
  const auto integrand = [&](const std::array<double, 2>& p) {
    const double difference =
        source.density(p[0], p[1]) - (candidate.scale * fitted.density(p[0], p[1]) + candidate.offset);
    return std::array<double, 1>{difference * difference};
  };
  const std::vector<double> edges = graded_breakpoints(window);
  std::vector<double> x_edges;
  for (auto it = edges.rbegin(); it != edges.rend(); ++it) x_edges.push_back(-*it);
  x_edges.insert(x_edges.end(), edges.begin() + 1, edges.end());
  std::vector<integrate::Box<2>> tiles;
  for (std::size_t i = 0; i + 1 < x_edges.size(); ++i) {
    for (std::size_t j = 0; j + 1 < edges.size(); ++j) tiles.push_back({{x_edges[i], edges[j]}, {x_edges[i + 1], edges[j + 1]}});
  }
  const auto result = integrate::integrate_adaptive<2, 1>(integrand, std::span<const integrate::Box<2>>(tiles), options);
  return from_result(result, 2.0);
}

}  // namespace pbrfit::brdf
