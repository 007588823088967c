#include "pbrfit/jobs/sweep/multi_lobe_sg_problem.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "pbrfit/brdf/multi_lobe_sg.hpp"
#include "pbrfit/brdf/multi_lobe_sg_error.hpp"

namespace pbrfit::jobs::sweep {
namespace {

enum SgModelIndex : std::size_t { free_amplitude, normalized };

double alpha_of(double r) { return std::max(r * r, 1e-3); }

class MultiLobeCell final : public CellTarget {
 public:
  MultiLobeCell(double view_angle, double r, const MultiLobeSgSettings& s)
      : view_angle_(view_angle),
        alpha_(alpha_of(r)),
        error_(alpha_, std::cos(view_angle), s.lobes, s.samples_per_strategy) {}

  pbrfit::sweep::CellProblem problem(std::size_t model, const std::vector<optimize::Parameter>& parameters) const override {
    pbrfit::sweep::CellProblem out;
    out.parameters = optimize::ParameterSpace(parameters);
    const auto start = lobe_start();
    out.default_start = {start.theta_center, start.spread, start.lambda};
    if (model == free_amplitude) out.default_start.push_back(start.amplitude);
    for (std::size_t k = 0; k < parameters.size(); ++k)
      out.default_start[k] = std::clamp(out.default_start[k], parameters[k].lower, parameters[k].upper);
    out.error = [this, model](std::span<const double> x) { return relative_error(model, x); };
    return out;
  }

  std::vector<double> outputs(std::size_t model, std::span<const double> x) const override {
    if (model == free_amplitude) return {};
    return {brdf::normalized_to(parameters(x), error_.lobe_count(), error_.target_integral()).amplitude};
  }

 private:
  brdf::MultiLobeSgParameters parameters(std::span<const double> x) const {
    return {x[0], x[1], x[2], x.size() > 3 ? x[3] : 1.0};
  }
  // The mirror direction, a narrow spread and a sharpness of the order of the lobe's width.
  brdf::MultiLobeSgParameters lobe_start() const {
    brdf::MultiLobeSgParameters p{view_angle_, 0.1 * view_angle_, std::clamp(2.0 / (alpha_ * alpha_), 1.0, 1e6), 1.0};
    return brdf::normalized_to(p, error_.lobe_count(), error_.target_integral());
  }
  double relative_error(std::size_t model, std::span<const double> x) const {
    const auto p = parameters(x);
    const double squared = model == free_amplitude ? error_.squared_error(p) : error_.squared_error_normalized(p);
    return std::sqrt(std::max(squared, 0.0) / error_.target_squared_norm());
  }

  double view_angle_;
  double alpha_;
  brdf::MultiLobeSgError error_;
};

class MultiLobeSgProblem final : public SweepProblem {
 public:
  explicit MultiLobeSgProblem(MultiLobeSgSettings s) : settings_(s) {}

  std::string description() const override {
    return "multi-lobe spherical Gaussian kernel for GGX environment lighting (Pesce & Iwanicki 2015, section 7.6)";
  }
  std::vector<ProblemAxis> axes() const override {
    using pbrfit::sweep::GridAxis;
    using pbrfit::sweep::Placement;
    return {{"view_angle", "angle theta_v between the normal and the view, radians", 0.0, 1.55,
             GridAxis{"view_angle", 0.0, 1.5, 16, Placement::centres}},
            {"roughness", "perceptual roughness r, alpha = max(r^2, 1e-3)", 0.0, 1.0,
             GridAxis{"roughness", 0.05, 1.0, 16, Placement::centres}}};
  }
  std::vector<ModelInfo> models() const override {
    using optimize::Transform;
    const double half_pi = 0.5 * std::numbers::pi;
    const std::vector<optimize::Parameter> shape = {{"theta_center", 0.0, half_pi, Transform::cosine},
                                                    {"spread", 0.0, half_pi, Transform::linear},
                                                    {"lambda", 1.0, 1e6, Transform::log}};
    auto with_amplitude = shape;
    with_amplitude.push_back({"amplitude", 1e-4, 1e4, Transform::log});
    const std::string error = "relative L2 error over the sphere, sqrt(integral (rho - kernel)^2 / integral rho^2)";
    return {{"free_amplitude", std::to_string(settings_.lobes) + " SG lobes, amplitude free", with_amplitude, error, {}},
            {"normalized", std::to_string(settings_.lobes) + " SG lobes integrating to the target's albedo", shape, error,
             {{"amplitude", "the norm that makes the kernel integrate to the target's albedo"}}}};
  }
  std::map<std::string, std::string> attributes() const override {
    return {{"lobes", std::to_string(settings_.lobes)},
            {"objective", "relative L2 over the sphere; QMC (Halton) with MIS of GGX and every SG lobe, balance heuristic"},
            {"samples", std::to_string(settings_.samples_per_strategy) + " per strategy"},
            {"constraint", "spread <= theta_center (clamped before the error is computed)"}};
  }
  std::unique_ptr<CellTarget> target(std::span<const double> c) const override {
    return std::make_unique<MultiLobeCell>(c[0], c[1], settings_);
  }

 private:
  MultiLobeSgSettings settings_;
};

}  // namespace

std::unique_ptr<SweepProblem> make_multi_lobe_sg_problem(const MultiLobeSgSettings& settings) {
  return std::make_unique<MultiLobeSgProblem>(settings);
}

}  // namespace pbrfit::jobs::sweep
