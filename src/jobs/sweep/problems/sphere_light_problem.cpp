#include "pbrfit/jobs/sweep/sphere_light_problem.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "pbrfit/brdf/sphere_light_models.hpp"
#include "pbrfit/brdf/sphere_light_target.hpp"
#include "pbrfit/core/error.hpp"

namespace pbrfit::jobs::sweep {
namespace {

using Model = std::function<double(const Vector3&)>;

enum SphereLightModelIndex : std::size_t { roughness_modification, capped_roughness, representative_point, smoothed_point };

class SphereLightCell final : public CellTarget {
 public:
  SphereLightCell(double r, double gamma, double incidence, const SphereLightSettings& s)
      : alpha_(r * r), light_(brdf::sphere_light_at(incidence, gamma)), p_(s.norm_p),
        target_(alpha_, light_, brdf::ViewGrid{s.view_panels, s.view_panels}, s.truth), norm_(target_.norm(p_)) {
    if (!target_.converged()) {
      char text[200];
      std::snprintf(text, sizeof text, "the sphere-light ground truth (alpha %.4g, half-angle %.4g, incidence %.4g) "
                    "missed its tolerance; raise objective.max_evaluations or objective.tolerance", alpha_, gamma, incidence);
      throw RunError(text);
    }
  }

  pbrfit::sweep::CellProblem problem(std::size_t model, const std::vector<optimize::Parameter>& parameters) const override {
    pbrfit::sweep::CellProblem out;
    out.parameters = optimize::ParameterSpace(parameters);
    out.default_start = default_start(model);
    for (std::size_t k = 0; k < parameters.size(); ++k)
      out.default_start[k] = std::clamp(out.default_start[k], parameters[k].lower, parameters[k].upper);
    out.error = [this, model](std::span<const double> x) { return relative_error(evaluator(model, x)); };
    return out;
  }

  std::vector<double> outputs(std::size_t model, std::span<const double>) const override {
    if (model == representative_point) {
      const double scale = brdf::karis_sphere_normalization(alpha_, light_);
      return {relative_error([&](const Vector3& v) { return brdf::representative_point_model(alpha_, scale, light_, v); })};
    }
    if (model == smoothed_point) {
      const double scale = brdf::course_smoothed_normalization(alpha_, light_);
      return {relative_error([&](const Vector3& v) {
        return brdf::smoothed_representative_point_model(alpha_, scale, brdf::course_representative_smoothness, light_, v);
      })};
    }
    return {};
  }

 private:
  std::vector<double> default_start(std::size_t model) const {
    switch (model) {
      case roughness_modification: return {alpha_};
      case capped_roughness: return {alpha_, 1.0, brdf::course_capped_smoothness};
      case representative_point: return {alpha_, brdf::karis_sphere_normalization(alpha_, light_)};
      default:
        return {alpha_, brdf::course_smoothed_normalization(alpha_, light_), brdf::course_representative_smoothness};
    }
  }
  Model evaluator(std::size_t model, std::span<const double> x) const {
    const std::vector<double> p(x.begin(), x.end());
    switch (model) {
      case roughness_modification:
        return [this, p](const Vector3& v) { return brdf::roughness_modification_model(p[0], light_, v); };
      case capped_roughness:
        return [this, p](const Vector3& v) { return brdf::capped_roughness_model(p[0], p[1], p[2], light_, v); };
      case representative_point:
        return [this, p](const Vector3& v) { return brdf::representative_point_model(p[0], p[1], light_, v); };
      default:
        return [this, p](const Vector3& v) {
          return brdf::smoothed_representative_point_model(p[0], p[1], p[2], light_, v);
        };
    }
  }
  double relative_error(const Model& model) const { return target_.error(model, p_) / norm_; }

  double alpha_;
  brdf::SphereLight light_;
  double p_;
  brdf::SphereLightTarget target_;
  double norm_;
};

ModelOutput anchor(const char* name, const char* who) {
  return {name, std::string("relative error of ") + who + " at the cell", "anchor_error", who, "error"};
}

class SphereLightProblem final : public SweepProblem {
 public:
  explicit SphereLightProblem(SphereLightSettings s) : settings_(std::move(s)) {}

  std::string description() const override { return "GGX lit by a uniform spherical light (Pesce & Iwanicki 2015, section 4)"; }
  std::vector<ProblemAxis> axes() const override {
    using pbrfit::sweep::GridAxis;
    using pbrfit::sweep::Placement;
    const double half_pi = 0.5 * std::numbers::pi;
    return {{"roughness", "perceptual roughness r, alpha = r^2", 0.01, 1.0, GridAxis{"roughness", 0.1, 1.0, 10, Placement::edges}},
            {"half_angle", "cone half-angle gamma of the light, radians (sin gamma = radius / distance)", 1e-3, half_pi,
             GridAxis{"half_angle", 0.05, 0.8, 6, Placement::edges}},
            {"incidence", "angle between the normal and the light's centre, radians", 0.0, half_pi,
             GridAxis{"incidence", 0.0, 1.2, 5, Placement::edges}}};
  }
  std::vector<ModelInfo> models() const override {
    using optimize::Transform;
    const optimize::Parameter alpha{"alpha_modified", 1e-3, 1.0, Transform::log};
    const std::string error = "relative L" + norm_text() + " error over the view hemisphere: |truth - model| / |truth|";
    return {{"roughness_modification", "GGX of a modified roughness alpha' towards the light's centre", {alpha}, error, {}},
            {"capped_roughness", "softmin(GGX of alpha', cap; s): roughness modification with a soft cap",
             {alpha, {"cap", 1e-3, 1e3, Transform::log}, {"smoothness", -32.0, -1.0, Transform::linear}}, error, {}},
            {"representative_point", "scale * GGX of alpha' towards the point of the light nearest the reflected ray",
             {alpha, {"scale", 1e-3, 1e2, Transform::log}}, error, {anchor("karis_error", "Karis 2013")}},
            {"smoothed_representative_point", "representative point with softmin(1, R / |c|; s) for the clamp",
             {alpha, {"scale", 1e-3, 1e2, Transform::log}, {"smoothness", -32.0, -0.5, Transform::linear}}, error,
             {anchor("course_error", "Pesce & Iwanicki 2015 (s = -3, fitted normalization)")}}};
  }
  std::map<std::string, std::string> attributes() const override {
    return {{"objective", "relative L" + norm_text() + " distance over views between ground truth and model"},
            {"views", std::to_string(225 * settings_.view_panels * settings_.view_panels) +
                          " nodes (product Kronrod rule about the mirror direction)"},
            {"ground_truth", "adaptive cubature over the light's cap, absolute tolerance " +
                                 std::to_string(settings_.truth.abs_tolerance)}};
  }
  std::unique_ptr<CellTarget> target(std::span<const double> c) const override {
    return std::make_unique<SphereLightCell>(c[0], c[1], c[2], settings_);
  }

 private:
  std::string norm_text() const { return std::isinf(settings_.norm_p) ? "inf" : std::to_string(int(settings_.norm_p)); }
  SphereLightSettings settings_;
};

}  // namespace

std::unique_ptr<SweepProblem> make_sphere_light_problem(const SphereLightSettings& settings) {
  return std::make_unique<SphereLightProblem>(settings);
}

}  // namespace pbrfit::jobs::sweep
