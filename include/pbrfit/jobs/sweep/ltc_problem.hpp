#pragma once
// Sweep problems `ltc` and `ltc_ggx`: isotropic LTC tables (Heitz et al. 2016) of lobes the brdf engine
// provides, one model (and one result group) per lobe, all fitted through ltc/isotropic_target.hpp.
//
// Axes, in texture order (the last axis is the texture's fast axis): the job's further axes of an expression
// BRDF first (outermost), then
//   sqrt_one_minus_cos  x = sqrt(1 - cos theta_v), cos theta_v = cos(min(acos(1 - x^2), 1.57)), [0, 1]
//   roughness           r in [0, 1], mapped to each lobe's parameter (brdf/brdf_families.hpp); absent for a
//                       measured material, whose table runs over the view alone.
// Each model fits (m00, m11, m02, m20) of isotropic_parameters.hpp with the albedo as amplitude; at
// normal view the lobe is rotationally symmetric (m11 = m00, m02 = m20 = 0). Error: the cubed error of
// fit_error.hpp (MIS over lobe and LTC samples, `objective_points` each). With fit_to = lights the fit is then
// refined on `training_quads` quad lights (default 256; ltc/polygon_lighting.hpp, their own seed): the objective is
// PolygonLights::score plus 0.01 x the cubed error relative to the lobe fit's, and that is the `error`.
//
// Outputs per cell, in order: error_cubed and error_l2 on the judge's finer lattice; for a lobe with a
// published table (GGX) the published texel's two errors (NaN off its grid); norm, fresnel, the forward
// matrix and the two RGBA textures of the reference shaders (ltc_1, ltc_2 with the sphere form-factor ratio
// where there is a roughness axis, else 0); with polygon_quads > 0 the polygon-lighting errors of
// ltc/polygon_lighting.hpp (median and 95th percentile over the quads, the number of quads counted) and the
// published texel's; then the lobe's own extra outputs (a measured material's RGB albedo); last, for a lobe
// with a published table, the published texel's own ltc_1 and ltc_2.
//
// Check render (ltc/table_render.hpp), with render_size > 0: each model's last-level table shades the plane
// under a rectangle light as a shader reads it (`ltc`), beside the lobe's own integral over the light
// (`reference`) and, for a lobe with a published table, that table read the same way (`published`); an
// image per roughness nearest 0.25, 0.5 and 0.75 (one image without a roughness axis), further axes at their
// middle value.
//
// Contract: as SweepProblem. A cell target builds each model's lobe, moments and estimators on first use, and
// is used by one thread.
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "pbrfit/brdf/lobe.hpp"
#include "pbrfit/jobs/sweep/sweep_problem.hpp"
#include "pbrfit/ltc/polygon_lighting.hpp"
#include "pbrfit/ltc/published_table.hpp"

namespace pbrfit::jobs::sweep {

// The lobe of one cell from its coordinates (the problem's axis values, in axis order).
using CellLobe = std::function<std::shared_ptr<const pbrfit::brdf::Lobe>(std::span<const double> coordinates)>;

struct LtcModelSpec {
  std::string name;
  std::string description;
  CellLobe lobe;
  std::shared_ptr<const ltc::PublishedLtcTable> published;  // anchors; null for none
  std::vector<ModelOutput> extra_outputs;                    // after the standard outputs
  std::function<std::vector<double>(const pbrfit::brdf::Lobe&, std::span<const double> coordinates)> extra_values;
};

struct LtcProblemSettings {
  std::string description;
  std::vector<ProblemAxis> extra_axes;  // outermost, before the view axis
  bool roughness_axis = true;
  std::string roughness_description = "roughness r in [0, 1], mapped to each model's parameter";
  std::vector<LtcModelSpec> models;
  std::size_t objective_points = 512;
  std::size_t moment_points = 4096;
  std::size_t metric_points = 4096;
  std::size_t polygon_quads = 64;  // judging lights; 0: no polygon-lighting errors
  ltc::QuadIntegralOptions polygon;
  enum class FitTo { lobe, lights } fit_to = FitTo::lobe;
  std::size_t training_quads = 256;          // lights a fit_to = lights table is refined on
  std::size_t refinement_evaluations = 150;  // ... and the objective evaluations it may spend
  std::size_t render_size = 64;              // pixels a side of the check render; 0: none
  std::map<std::string, std::string> attributes;  // further group attributes
};

std::unique_ptr<SweepProblem> make_ltc_problem(LtcProblemSettings settings);

// cos theta_v of the view axis value x = sqrt(1 - cos theta_v), with theta_v capped at 1.57 as published.
double ltc_cos_theta(double x);

}  // namespace pbrfit::jobs::sweep
