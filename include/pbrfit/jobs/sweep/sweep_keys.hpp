#pragma once
// The keys of a `sweep` job's section as values (docs/job-files.md, kind `sweep`). Each key is declared once,
// with its type, range, default and meaning, where it is bound to its member here: the section's own keys in
// sweep_keys.cpp, `objective` beside the problem catalogue that says which problem reads which of its keys,
// `expression` and `brdf` beside the problems that read them.
//
// Keys whose use depends on the problem (an axis's ends, a parameter's bounds, the objective's keys, the
// problem-specific sections) keep whether and where the file wrote them (spec::Located), so the problem
// that reads them can refuse them at their position; a key without a default that is not written keeps its
// member's initial value. Problems choose their own defaults for the objective's keys (std::optional).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "pbrfit/gp/expression_parser.hpp"
#include "pbrfit/integrate/adaptive_cubature.hpp"
#include "pbrfit/jobs/sweep/expression_problem.hpp"
#include "pbrfit/optimize/parameter_transform.hpp"
#include "pbrfit/spec/keys.hpp"
#include "pbrfit/sweep/cell_fit.hpp"
#include "pbrfit/sweep/grid_axis.hpp"

namespace pbrfit::jobs::sweep {

// One entry of `axes`: changes to one of the problem's axes (or, for problems that let the job add axes,
// a whole axis).
struct AxisKeys {
  spec::Located<std::string> name;
  spec::Located<double> from, to;
  spec::Located<std::int64_t> count;
  spec::Located<pbrfit::sweep::Placement> samples;  // edges unless written
};

struct MarchKeys {
  spec::Located<std::string> axis;
  bool reverse = false;
};

// One entry of `parameters`: changes to a model parameter's bounds and search domain.
struct ParameterKeys {
  spec::Located<std::string> name, model;
  spec::Located<double> lower, upper;
  spec::Located<optimize::Transform> transform;
  spec::Located<double> start;  // problem `expression` only
};

struct FitKeys {
  pbrfit::sweep::GlobalPolicy global_search = pbrfit::sweep::GlobalPolicy::when_poor;
  double poor_ratio = 2.0, poor_absolute = 0.0;
  std::size_t warm_evaluations = 400;
  double warm_step = 0.01;
  std::size_t max_evaluations = 20'000;
};

// `objective`: every key any problem reads; none has a default, each problem chooses its own.
struct ObjectiveKeys {
  std::optional<std::size_t> samples, judge_samples, polygon_quads, render_size;
  std::optional<double> polygon_tolerance;
  spec::Located<bool> fit_to_lights;  // fit_to: lights
  spec::Located<std::size_t> training_quads;  // read with fit_to: lights only
  spec::Located<double> norm{2.0, false, {}, {}};  // the p of the L^p norm: 1, 2, 3 or +inf
  spec::Located<bool> qmc;            // integrator: qmc
  std::optional<double> tolerance;
  spec::Located<double> coarse_tolerance;
  std::optional<std::size_t> max_evaluations, views, lobes;
  std::optional<double> window, distance;
  std::vector<spec::WrittenKey> written;  // refused where the problem does not read them
};

// `expression` (problem `expression`): the domain, the target and the model.
struct ExpressionKeys {
  ExpressionDomain domain = ExpressionDomain::interval;
  spec::Located<std::vector<std::string>> inputs;
  spec::Located<std::vector<double>> lower, upper;
  spec::Located<std::string> target, model;
};

// `brdf` (problem `ltc`): a BRDF expression or a measured material instead of the built-in families.
struct BrdfKeys {
  spec::Located<std::string> expression, material, merl_directory, cache;
  std::optional<std::string> name;
};

struct SweepKeys {
  spec::Located<std::string> problem;
  spec::Located<std::vector<std::string>> models;
  spec::Located<std::vector<AxisKeys>> axes;
  spec::Located<std::int64_t> levels;
  std::optional<MarchKeys> march;
  spec::Located<std::vector<ParameterKeys>> parameters;
  spec::Located<std::vector<std::string>> projections;
  FitKeys fit;
  ObjectiveKeys objective;
  spec::Located<ExpressionKeys> expression;  // written: the section is there
  spec::Located<BrdfKeys> brdf;
};

const spec::Keys<SweepKeys>& sweep_keys();
spec::Keys<ObjectiveKeys> objective_keys();    // problem_catalogue.cpp
spec::Keys<ExpressionKeys> expression_keys();  // expression_settings.cpp
spec::Keys<BrdfKeys> brdf_keys();              // ltc_settings.cpp

// `tolerance` (or `tolerance_default`) and `max_evaluations` as adaptive-cubature options.
integrate::AdaptiveOptions integration(const ObjectiveKeys& objective, double tolerance_default);
// `coarse_tolerance` (or the larger of `fallback` and the final tolerance); InputError when it is written
// below the final tolerance.
double coarse_tolerance(const ObjectiveKeys& objective, double final_tolerance, double fallback);

// An expression text of the job, parsed; a parse error is an InputError at its key naming the line and
// column within the text.
gp::ParsedExpression parse_expression_at(const spec::Located<std::string>& text, const gp::ExpressionNames& names);

}  // namespace pbrfit::jobs::sweep
