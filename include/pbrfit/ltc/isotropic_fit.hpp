#pragma once
// Fitting one cell of an isotropic LTC table (Heitz et al. 2016, section 4) on its own, outside a sweep: the
// LTC of a lobe (brdf/lobe.hpp; GGX for the published table) in the paper's parametrization with the tilt
// m20 freed (see isotropic_parameters.hpp), with the albedo as amplitude, minimizing the cubed error of
// isotropic_target.hpp by the optimize engine's Nelder-Mead with restarts from a start the caller chooses:
// the fit of a neighbouring cell when marching through a table as the paper does (ggx_table.hpp), or the
// identity.
//
// The search runs over p = (ln m00, ln m11, m02, m20) in the box ln m in [ln 1e-6, ln 8], m02 and m20 in
// [-4, 4] (a start outside is clamped into it; points with m00 - m02 m20 <= 0 are infeasible); at normal view
// (cos theta_v = 1) over ln m alone, with m00 = m11 and m02 = m20 = 0.
//
// Contract: the same inputs give bitwise the same result; objective evaluations <= max_evaluations; `error` is
// measured on a lattice of metric_points points (a judge independent of the objective's lattice when the
// counts differ), and is left at zero when metric_points = 0.
#include <cstddef>
#include <memory>

#include "pbrfit/brdf/lobe.hpp"
#include "pbrfit/ltc/fit_error.hpp"
#include "pbrfit/ltc/lobe_moments.hpp"
#include "pbrfit/ltc/isotropic_parameters.hpp"
#include "pbrfit/ltc/shader_form.hpp"
#include "pbrfit/geometry/vector.hpp"
#include "pbrfit/optimize/nelder_mead.hpp"
#include "pbrfit/optimize/stop_reason.hpp"

namespace pbrfit::ltc {

// A small warm-start simplex (1 % of the box per dimension), up to 3 restarts, convergence when the simplex
// spans 1e-4 of the box and its values agree to a relative 1e-5.
optimize::NelderMeadOptions default_cell_search();

struct CellFitOptions {
  std::size_t objective_points = 512;  // per sampling strategy
  std::size_t moment_points = 4096;
  std::size_t metric_points = 4096;
  std::size_t max_evaluations = 300;
  optimize::NelderMeadOptions search = default_cell_search();
};

struct CellFit {
  IsotropicParameters parameters;
  Matrix3 matrix = Matrix3::Identity();  // M, mapping cosine directions to the lobe
  ShaderForm shader{};                   // the published ltc_1 form of M
  LobeMoments moments;                   // albedo (amplitude), fresnel, average direction
  double objective = 0.0;                // the cubed error on the objective's lattice
  FitError error;                        // both errors on the metric lattice
  std::size_t evaluations = 0;
  optimize::StopReason stop = optimize::StopReason::budget;
};

CellFit fit_isotropic_cell(std::shared_ptr<const brdf::Lobe> lobe, const IsotropicParameters& start,
                           const CellFitOptions& options);

}  // namespace pbrfit::ltc
