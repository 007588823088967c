#include "pbrfit/jobs/sweep/ltc_problem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pbrfit/ltc/isotropic_target.hpp"
#include "pbrfit/ltc/shader_form.hpp"
#include "pbrfit/ltc/sphere_form_factor.hpp"

#include "ltc_render.hpp"

namespace pbrfit::jobs::sweep {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double max_theta = 1.57;  // the published tables' cap on theta_v

ltc::IsotropicParameters from(std::span<const double> p) { return {p[0], p[1], p[2], p[3]}; }

// The published texel at these coordinates, when they lie on its grid.
const ltc::PublishedLtcCell* published_texel(const ltc::PublishedLtcTable* table, double x, double r) {
  if (!table) return nullptr;
  const double last = table->size() - 1;
  const double a = r * last, t = x * last;
  if (std::abs(a - std::round(a)) > 1e-9 || std::abs(t - std::round(t)) > 1e-9) return nullptr;
  return table->find(int(std::round(a)), int(std::round(t)));
}

// The problem's axes: further axes, then the view, then the roughness.
struct AxisLayout {
  std::size_t view = 0;
  std::optional<std::size_t> roughness;
};

// One model's target in one cell: the lobe, its moments and estimators, the polygon references.
class LtcModelCell {
 public:
  LtcModelCell(const LtcModelSpec& spec, const LtcProblemSettings& settings, const std::vector<ltc::Quad>& quads,
               const std::vector<ltc::Quad>& training, std::span<const double> coordinates, const AxisLayout& layout)
      : spec_(spec),
        settings_(settings),
        quads_(quads),
        training_(training),
        coordinates_(coordinates.begin(), coordinates.end()),
        x_(coordinates[layout.view]),
        r_(layout.roughness ? coordinates[*layout.roughness] : nan),
        target_(spec.lobe(coordinates),
                {settings.objective_points, settings.moment_points, settings.metric_points}),
        published_(layout.roughness ? published_texel(spec.published.get(), x_, r_) : nullptr) {}

  pbrfit::sweep::CellProblem problem(const std::vector<optimize::Parameter>& parameters) const {
    pbrfit::sweep::CellProblem out;
    auto searched = parameters;
    if (target_.symmetric()) {  // only m00 is free; m11 follows it
      searched[1].lower = searched[1].upper = 1.0;
      searched[2].lower = searched[2].upper = 0.0;
      searched[3].lower = searched[3].upper = 0.0;
      out.canonical = [](std::span<double> p) { p[1] = p[0]; };
    }
    out.parameters = optimize::ParameterSpace(searched);
    out.default_start = {1.0, 1.0, 0.0, 0.0};
    out.error = [this](std::span<const double> p) { return target_.objective(from(p)); };
    if (settings_.fit_to == LtcProblemSettings::FitTo::lights) {
      out.refinement_evaluations = settings_.refinement_evaluations;
      out.refinement = [this](std::span<const double>, double lobe_error) -> optimize::Objective {
        const ltc::PolygonLights& lights = lights_of(training_lights_, training_);
        return [this, &lights, lobe_error](std::span<const double> p) {
          const double cubed = target_.objective(from(p));
          if (!std::isfinite(cubed)) return cubed;
          return lights.score(target_.distribution(target_.matrix(from(p)))) +
                 0.01 * cubed / std::max(lobe_error, 1e-300);
        };
      };
    }
    return out;
  }

  std::vector<double> outputs(std::span<const double> p) const {
    const Matrix3 m = target_.matrix(from(p));
    const auto& moments = target_.moments();
    const auto ours = target_.judge(m);
    std::vector<double> out = {ours.cubed, ours.l2, ours.target_l2 > 0.0 ? ours.l2 / ours.target_l2 : nan};
    std::optional<ltc::LtcDistribution> theirs;
    if (spec_.published) {
      if (published_) {
        theirs.emplace(ltc::matrix_from_shader_form(published_->ltc1), published_->norm);
        const auto judged = target_.judge(ltc::matrix_from_shader_form(published_->ltc1));
        out.insert(out.end(), {judged.cubed, judged.l2});
      } else {
        out.insert(out.end(), {nan, nan});
      }
    }
    out.push_back(moments.albedo);
    out.push_back(moments.fresnel);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) out.push_back(m(i, j));
    for (double v : ltc::shader_form(m)) out.push_back(v);
    const double sphere = std::isnan(r_) ? 0.0 : ltc::sphere_form_factor_ratio(2.0 * r_ - 1.0, x_);
    for (double v : {moments.albedo, moments.fresnel, 0.0, sphere}) out.push_back(v);
    if (!quads_.empty()) append_polygon_errors(out, target_.distribution(m), theirs ? &*theirs : nullptr);
    if (spec_.extra_values) {
      const auto extra = spec_.extra_values(target_.lobe(), coordinates_);
      out.insert(out.end(), extra.begin(), extra.end());
    }
    if (spec_.published) {  // the published texel's own textures, for engines that compare or fall back
      if (published_) {
        out.insert(out.end(), published_->ltc1.begin(), published_->ltc1.end());
        out.insert(out.end(), {published_->norm, published_->fresnel, 0.0, published_->sphere});
      } else {
        out.insert(out.end(), 8, nan);
      }
    }
    return out;
  }

 private:
  const ltc::PolygonLights& lights_of(std::optional<ltc::PolygonLights>& lights, const std::vector<ltc::Quad>& quads) const {
    if (!lights) {
      const pbrfit::brdf::Lobe& lobe = target_.lobe();
      lights.emplace(lobe, quads, lobe.peak().value_or(target_.moments().average_direction), settings_.polygon);
    }
    return *lights;
  }

  void append_polygon_errors(std::vector<double>& out, const ltc::LtcDistribution& ours,
                             const ltc::LtcDistribution* theirs) const {
    const ltc::PolygonLights& lights = lights_of(judging_lights_, quads_);
    const auto errors = lights.errors(ours);
    out.insert(out.end(), {errors.median, errors.p95, errors.weighted, double(errors.counted)});
    if (!spec_.published) return;
    if (!theirs) {
      out.insert(out.end(), {nan, nan, nan});
      return;
    }
    const auto anchor = lights.errors(*theirs);
    out.insert(out.end(), {anchor.median, anchor.p95, anchor.weighted});
  }

  const LtcModelSpec& spec_;
  const LtcProblemSettings& settings_;
  const std::vector<ltc::Quad>& quads_;
  const std::vector<ltc::Quad>& training_;
  std::vector<double> coordinates_;
  double x_, r_;
  ltc::IsotropicTarget target_;
  const ltc::PublishedLtcCell* published_;
  mutable std::optional<ltc::PolygonLights> judging_lights_, training_lights_;  // made on first use
};

class LtcCell final : public CellTarget {
 public:
  LtcCell(const LtcProblemSettings& settings, const std::vector<ltc::Quad>& quads,
          const std::vector<ltc::Quad>& training, std::span<const double> coordinates, const AxisLayout& layout)
      : settings_(settings), quads_(quads), training_(training), coordinates_(coordinates.begin(), coordinates.end()),
        layout_(layout), models_(settings.models.size()) {}

  pbrfit::sweep::CellProblem problem(std::size_t model, const std::vector<optimize::Parameter>& parameters) const override {
    return cell(model).problem(parameters);
  }
  std::vector<double> outputs(std::size_t model, std::span<const double> parameters) const override {
    return cell(model).outputs(parameters);
  }

 private:
  const LtcModelCell& cell(std::size_t model) const {
    if (!models_[model])
      models_[model] =
          std::make_unique<LtcModelCell>(settings_.models[model], settings_, quads_, training_, coordinates_, layout_);
    return *models_[model];
  }

  const LtcProblemSettings& settings_;
  const std::vector<ltc::Quad>& quads_;
  const std::vector<ltc::Quad>& training_;
  std::vector<double> coordinates_;
  AxisLayout layout_;
  mutable std::vector<std::unique_ptr<LtcModelCell>> models_;  // built on first use (one thread per cell)
};

std::vector<ModelOutput> standard_outputs(const LtcModelSpec& spec, bool polygons) {
  const std::string heitz = "Heitz et al. 2016 (published table)";
  std::vector<ModelOutput> out = {
      {"error_cubed", "integral of |D - rho|^3 over the sphere, on the judge's finer lattice", "error"},
      {"error_l2", "sqrt(integral of (D - rho)^2) over the sphere, on the judge's finer lattice", "error"},
      {"error_l2_relative",
       "error_l2 over the target's own L2 norm sqrt(integral of rho^2): 0 exact, 1 as far off as no lobe at all",
       "error"}};
  if (spec.published) {
    out.push_back({"published_error_cubed", "the published texel's cubed error, same judge and amplitude",
                   "anchor_error", heitz, "error_cubed"});
    out.push_back({"published_error_l2", "the published texel's L2 error, same judge and amplitude", "anchor_error",
                   heitz, "error_l2"});
  }
  const std::vector<ModelOutput> textures = {
      {"norm", "albedo of the lobe: the LTC amplitude (published ltc_2.x)"},
      {"fresnel", "integral of rho (1 - v.h)^5: the Schlick Fresnel term (published ltc_2.y)"},
      {"matrix", "the forward matrix M, row-major (cosine directions to the lobe)", "output", "", "", 9},
      {"ltc_1", "texture 1 of the reference shaders: inverse of M over its middle entry, (m00, m20, m02, m22)",
       "output", "", "", 4, store::ValueType::f32},
      {"ltc_2", "texture 2 of the reference shaders: (norm, fresnel, 0, sphere form factor ratio)", "output", "", "",
       4, store::ValueType::f32}};
  out.insert(out.end(), textures.begin(), textures.end());
  if (polygons) {
    out.push_back({"polygon_error_median",
                   "median over the quad lights inside the lobe of |norm x LTC integral - the lobe's integral| / the "
                   "lobe's (inside: the lobe's mean over the light is at least 1 % of its peak)",
                   "error"});
    out.push_back({"polygon_error_p95", "95th percentile of the same relative errors", "error"});
    out.push_back({"polygon_error_weighted",
                   "sum over all quad lights of |norm x LTC integral - the lobe's integral| / sum of the lobe's",
                   "error"});
    out.push_back({"polygon_lights", "quad lights inside the lobe (those the median and p95 count)", "count"});
    if (spec.published) {
      out.push_back({"published_polygon_error_median", "the published texel's median polygon-lighting error, same lights",
                     "anchor_error", heitz, "polygon_error_median"});
      out.push_back({"published_polygon_error_p95", "the published texel's 95th-percentile polygon-lighting error",
                     "anchor_error", heitz, "polygon_error_p95"});
      out.push_back({"published_polygon_error_weighted", "the published texel's weighted polygon-lighting error",
                     "anchor_error", heitz, "polygon_error_weighted"});
    }
  }
  out.insert(out.end(), spec.extra_outputs.begin(), spec.extra_outputs.end());
  if (spec.published) {
    out.push_back({"published_ltc_1", "the published table's ltc_1 texel (NaN off its grid), for comparison", "output",
                   "", "", 4, store::ValueType::f32});
    out.push_back({"published_ltc_2", "the published table's ltc_2 texel (NaN off its grid)", "output", "", "", 4,
                   store::ValueType::f32});
  }
  return out;
}

class LtcProblem final : public SweepProblem {
 public:
  explicit LtcProblem(LtcProblemSettings settings)
      : settings_(std::move(settings)),
        quads_(ltc::random_quads(settings_.polygon_quads)),
        training_(settings_.fit_to == LtcProblemSettings::FitTo::lights
                      ? ltc::random_quads(settings_.training_quads, ltc::training_quad_seed)
                      : std::vector<ltc::Quad>{}) {
    layout_.view = settings_.extra_axes.size();
    if (settings_.roughness_axis) layout_.roughness = layout_.view + 1;
  }

  std::string description() const override { return settings_.description; }

  std::vector<ProblemAxis> axes() const override {
    using pbrfit::sweep::GridAxis;
    using pbrfit::sweep::Placement;
    std::vector<ProblemAxis> out = settings_.extra_axes;
    out.push_back({"sqrt_one_minus_cos", "x = sqrt(1 - cos theta_v); cos theta_v = cos(min(acos(1 - x^2), 1.57))", 0.0,
                   1.0, GridAxis{"sqrt_one_minus_cos", 0.0, 1.0, 64, Placement::edges}});
    if (settings_.roughness_axis)
      out.push_back({"roughness", settings_.roughness_description, 0.0, 1.0,
                     GridAxis{"roughness", 0.0, 1.0, 64, Placement::edges}});
    return out;
  }

  std::vector<ModelInfo> models() const override {
    using optimize::Transform;
    std::vector<ModelInfo> out;
    for (const auto& spec : settings_.models)
      out.push_back({spec.name,
                     "M = [X Y Z] [[m00, 0, m02], [0, m11, 0], [m20, 0, 1]] in the frame of the lobe's average "
                     "direction; lobe: " + spec.description,
                     {{"m00", 1e-6, 8.0, Transform::log},
                      {"m11", 1e-6, 8.0, Transform::log},
                      {"m02", -4.0, 4.0, Transform::linear},
                      {"m20", -4.0, 4.0, Transform::linear}},
                     settings_.fit_to == LtcProblemSettings::FitTo::lights
                         ? "the lights objective: rms relative error over the training lights inside the lobe + "
                           "their weighted error + 0.01 x the cubed error over the lobe fit's"
                         : "the fitting objective: integral of |D - rho|^3 over the sphere (MIS, objective lattice)",
                     standard_outputs_of(spec)});
    if (settings_.metric_points > 0)  // the judge's errors exist: the headline gives the relative one
      for (auto& model : out) model.headline_output = "error_l2_relative", model.headline_label = "relative L2 error";
    return out;
  }

  std::vector<ModelOutput> standard_outputs_of(const LtcModelSpec& spec) const {
    return standard_outputs(spec, settings_.polygon_quads > 0);
  }

  std::map<std::string, std::string> attributes() const override {
    std::map<std::string, std::string> out = {
        {"objective", "cubed error, MIS of the lobe's own samples and LTC samples, balance heuristic"},
        {"objective_points", std::to_string(settings_.objective_points) + " per strategy"},
        {"judge_points", std::to_string(settings_.metric_points) + " per strategy"},
        {"texture_layout", settings_.roughness_axis
                               ? "ltc_1 and ltc_2 are [sqrt_one_minus_cos][roughness][rgba]: RGBA textures with "
                                 "roughness on the fast axis, as the reference shaders sample them"
                               : "ltc_1 and ltc_2 are [sqrt_one_minus_cos][rgba]: one RGBA texel per view"}};
    if (settings_.fit_to == LtcProblemSettings::FitTo::lights)
      out["fit_to"] = "lights: the lobe fit refined on " + std::to_string(settings_.training_quads) +
                      " training quad lights, seed " + std::to_string(ltc::training_quad_seed);
    if (settings_.polygon_quads > 0) {
      out["polygon_quads"] = std::to_string(settings_.polygon_quads) + " quad lights, seed " +
                             std::to_string(ltc::polygon_quad_seed) + " (docs/results-sweep.md)";
      out["polygon_tolerance"] = std::to_string(settings_.polygon.relative_tolerance) +
                                 " relative, adaptive cubature of the lobe over each quad";
    }
    for (const auto& [key, value] : settings_.attributes) out[key] = value;
    return out;
  }

  std::unique_ptr<CellTarget> target(std::span<const double> c) const override {
    return std::make_unique<LtcCell>(settings_, quads_, training_, c, layout_);
  }

  std::optional<RenderPlan> render_plan(const pbrfit::sweep::LevelGrid& grid) const override {
    return ltc_render_plan(settings_, grid, layout_.view, layout_.roughness);
  }

  std::vector<double> render(std::size_t model, const RenderPlan& plan, std::size_t image, std::size_t first_row,
                             std::size_t rows, std::span<const std::vector<double>> outputs) const override {
    const auto& spec = settings_.models.at(model);
    return ltc_render(spec, standard_outputs_of(spec), plan, image, first_row, rows, layout_.view, outputs);
  }

 private:
  LtcProblemSettings settings_;
  std::vector<ltc::Quad> quads_;
  std::vector<ltc::Quad> training_;
  AxisLayout layout_;
};

}  // namespace

double ltc_cos_theta(double x) {
  return std::cos(std::min(std::acos(std::clamp(1.0 - x * x, -1.0, 1.0)), max_theta));
}

std::unique_ptr<SweepProblem> make_ltc_problem(LtcProblemSettings settings) {
  return std::make_unique<LtcProblem>(std::move(settings));
}

}  // namespace pbrfit::jobs::sweep
