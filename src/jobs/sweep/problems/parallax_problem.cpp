#include "pbrfit/jobs/sweep/parallax_problem.hpp"

#include <cmath>

#include "pbrfit/brdf/parallax_fit_error.hpp"

namespace pbrfit::jobs::sweep {
namespace {

class ParallaxCell final : public CellTarget {
 public:
  ParallaxCell(double r, double second, const ParallaxSettings& s) : alpha_(r * r), second_(second), settings_(s) {
    source_norm_ = squared_error({0.0, 0.0, 0.0, 0.0}, settings_.integration.abs_tolerance);
  }

  pbrfit::sweep::CellProblem problem(std::size_t, const std::vector<optimize::Parameter>& parameters) const override {
    pbrfit::sweep::CellProblem out;
    out.parameters = optimize::ParameterSpace(parameters);
    out.default_start = {std::clamp(alpha_, parameters[0].lower, parameters[0].upper), 1.0, 0.0};
    if (parameters.size() > 3) out.default_start.push_back(0.0);
    out.error = [this](std::span<const double> x, double tolerance) {
      const brdf::PerpendicularCandidate c{x[0], x[1], x[2], x.size() > 3 ? x[3] : 0.0};
      return std::sqrt(std::max(squared_error(c, tolerance), 0.0) / source_norm_);
    };
    return out;
  }

  std::vector<double> outputs(std::size_t, std::span<const double>) const override { return {}; }

 private:
  double squared_error(const brdf::PerpendicularCandidate& c, double tolerance) const {
    integrate::AdaptiveOptions options = settings_.integration;
    options.abs_tolerance = tolerance * source_scale();
    if (settings_.study == ParallaxStudy::distance)
      return brdf::distance_fit_error(alpha_, second_, c, settings_.window, options).squared;
    return brdf::angle_fit_error(alpha_, second_, settings_.distance, c, settings_.window, options).squared;
  }
  // The tolerance is relative to the source's squared norm once it is known (absolute before).
  double source_scale() const { return source_norm_ > 0.0 ? source_norm_ : 1.0; }

  double alpha_, second_;
  ParallaxSettings settings_;
  double source_norm_ = 0.0;
};

class ParallaxProblem final : public SweepProblem {
 public:
  explicit ParallaxProblem(ParallaxSettings s) : settings_(s) {}

  std::string description() const override {
    return angle() ? "perpendicular lobe matching a GGX lobe projected on a plane at an angle (Pesce & Iwanicki 2015, "
                     "section 8)"
                   : "perpendicular lobe at distance 1 matching a GGX lobe projected on a plane from a distance "
                     "(Pesce & Iwanicki 2015, section 8)";
  }
  std::vector<ProblemAxis> axes() const override {
    using pbrfit::sweep::GridAxis;
    using pbrfit::sweep::Placement;
    ProblemAxis roughness{"roughness", "perceptual roughness r of the source lobe, alpha = r^2", 0.02, 1.0,
                          GridAxis{"roughness", 0.1, 1.0, 10, Placement::edges}};
    if (angle())
      return {roughness, {"angle", "angle between the source lobe's axis and the plane normal, radians", 0.0, 1.5,
                          GridAxis{"angle", 0.0, 1.2, 7, Placement::edges}}};
    return {roughness, {"distance", "distance from the source lobe's origin to the plane (the candidate's is 1)",
                        0.05, 20.0, GridAxis{"distance", 0.25, 4.0, 8, Placement::edges}}};
  }
  std::vector<ModelInfo> models() const override {
    using optimize::Transform;
    std::vector<optimize::Parameter> p = {{"alpha_modified", 1e-3, 1.0, Transform::log},
                                          {"scale", 0.1, 10.0, Transform::log},
                                          {"offset", -0.1, 0.1, Transform::linear}};
    if (angle()) p.push_back({"shift", 0.0, 1.0, Transform::linear});
    return {{"perpendicular_lobe",
             angle() ? "scale * P(alpha') perpendicular above shift * (the foot of the source's origin) + offset"
                     : "scale * P(alpha') perpendicular at distance 1 + offset",
             p, "relative L2 error over the window, sqrt(integral (P_source - candidate)^2 / integral P_source^2)", {}}};
  }
  std::map<std::string, std::string> attributes() const override {
    std::map<std::string, std::string> a = {{"window", std::to_string(settings_.window)},
                                            {"tolerance", std::to_string(settings_.integration.abs_tolerance) +
                                                              " relative to integral P_source^2 (final)"},
                                            {"coarse_tolerance", std::to_string(settings_.coarse_tolerance)}};
    if (angle()) a["distance"] = std::to_string(settings_.distance);
    return a;
  }
  optimize::ToleranceSchedule tolerance_schedule() const override {
    return {settings_.coarse_tolerance, settings_.integration.abs_tolerance, 1e-3, 4};
  }
  std::unique_ptr<CellTarget> target(std::span<const double> c) const override {
    return std::make_unique<ParallaxCell>(c[0], c[1], settings_);
  }

 private:
  bool angle() const { return settings_.study == ParallaxStudy::angle; }
  ParallaxSettings settings_;
};

}  // namespace

std::unique_ptr<SweepProblem> make_parallax_problem(const ParallaxSettings& settings) {
  return std::make_unique<ParallaxProblem>(settings);
}

}  // namespace pbrfit::jobs::sweep
