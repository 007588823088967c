#pragma once
// Sweep problem `ltc_ggx`: the isotropic LTC table of GGX (Heitz et al. 2016) on the published grid.
// Axes, in texture order (the last axis is the texture's fast axis):
//   sqrt_one_minus_cos  x = sqrt(1 - cos theta_v), cos theta_v = cos(min(acos(1 - x^2), 1.57)), [0, 1]
//   roughness           perceptual r, alpha = max(r^2, 1e-5), [0, 1]
// Model `ltc`: (m00, m11, m02, m20) of isotropic_parameters.hpp with the albedo as amplitude; at normal
// view the lobe is rotationally symmetric (m11 = m00, m02 = m20 = 0). Error: the cubed error of
// fit_error.hpp (MIS over target and LTC samples, `samples` points each). Outputs: the errors judged on a
// finer lattice (cubed and L2), the published table's errors at the same texel as anchors (NaN off its
// grid), norm and Fresnel, the forward matrix, and the two RGBA textures of the reference shaders.
#include <cstddef>
#include <memory>

#include "pbrfit/jobs/sweep/sweep_problem.hpp"
#include "pbrfit/ltc/published_table.hpp"

namespace pbrfit::jobs::sweep {

struct LtcGgxSettings {
  std::size_t objective_points = 512;
  std::size_t moment_points = 4096;
  std::size_t metric_points = 4096;
  std::shared_ptr<const ltc::PublishedLtcTable> published;  // null: no anchors
};

std::unique_ptr<SweepProblem> make_ltc_ggx_problem(const LtcGgxSettings& settings);

}  // namespace pbrfit::jobs::sweep
