#include "pbrfit/jobs/sweep/ltc_ggx_problem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pbrfit/ltc/distribution.hpp"
#include "pbrfit/ltc/fit_error.hpp"
#include "pbrfit/ltc/ggx_moments.hpp"
#include "pbrfit/ltc/ggx_table.hpp"
#include "pbrfit/ltc/isotropic_parameters.hpp"
#include "pbrfit/ltc/shader_form.hpp"
#include "pbrfit/ltc/sphere_form_factor.hpp"

namespace pbrfit::jobs::sweep {
namespace {

using ltc::Matrix3;
using ltc::Vector3;

const ltc::GgxTableLayout published_layout{};
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

ltc::IsotropicParameters from(std::span<const double> p) { return {p[0], p[1], p[2], p[3]}; }

// The published texel at these coordinates, when they lie on its grid.
const ltc::PublishedLtcCell* published_texel(const ltc::PublishedLtcTable* table, double x, double r) {
  if (!table) return nullptr;
  const double last = table->size() - 1;
  const double a = r * last, t = x * last;
  if (std::abs(a - std::round(a)) > 1e-9 || std::abs(t - std::round(t)) > 1e-9) return nullptr;
  return table->find(int(std::round(a)), int(std::round(t)));
}

class LtcCell final : public CellTarget {
 public:
  LtcCell(double x, double r, const LtcGgxSettings& settings)
      : target_(std::max(r * r, published_layout.min_alpha), cos_theta(x)),
        x_(x),
        r_(r),
        moments_(ltc::measure_moments(target_, settings.moment_points)),
        objective_(target_, settings.objective_points),
        judge_(target_, settings.metric_points),
        published_(published_texel(settings.published.get(), x, r)) {
    if (symmetric()) moments_.average_direction = Vector3::UnitZ();
  }

  pbrfit::sweep::CellProblem problem(std::size_t, const std::vector<optimize::Parameter>& parameters) const override {
    pbrfit::sweep::CellProblem out;
    auto searched = parameters;
    if (symmetric()) {  // only m00 is free; m11 follows it
      searched[1].lower = searched[1].upper = 1.0;
      searched[2].lower = searched[2].upper = 0.0;
      searched[3].lower = searched[3].upper = 0.0;
      out.canonical = [](std::span<double> p) { p[1] = p[0]; };
    }
    out.parameters = optimize::ParameterSpace(searched);
    out.default_start = {1.0, 1.0, 0.0, 0.0};
    out.error = [this](std::span<const double> p) { return cubed_error(p); };
    return out;
  }

  std::vector<double> outputs(std::size_t, std::span<const double> p) const override {
    const Matrix3 m = matrix(p);
    const ltc::LtcDistribution ltc(m, moments_.albedo);
    const auto ours = judge_.errors(ltc);
    std::vector<double> out = {ours.cubed, ours.l2};
    append_published_errors(out);
    out.push_back(moments_.albedo);
    out.push_back(moments_.fresnel);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) out.push_back(m(i, j));
    for (double v : ltc::shader_form(m)) out.push_back(v);
    const double sphere = ltc::sphere_form_factor_ratio(2.0 * r_ - 1.0, x_);
    for (double v : {moments_.albedo, moments_.fresnel, 0.0, sphere}) out.push_back(v);
    return out;
  }

 private:
  static double cos_theta(double x) {
    return std::cos(std::min(std::acos(std::clamp(1.0 - x * x, -1.0, 1.0)), published_layout.max_theta));
  }
  bool symmetric() const { return target_.view().z() >= 1.0; }
  Matrix3 matrix(std::span<const double> p) const {
    auto parameters = from(p);
    if (symmetric()) parameters = {p[0], p[0], 0.0, 0.0};
    return ltc::isotropic_ltc_matrix(parameters, moments_.average_direction);
  }
  double cubed_error(std::span<const double> p) const {
    const double det = symmetric() ? p[0] : p[0] - p[2] * p[3];
    if (!(det > 1e-300)) return std::numeric_limits<double>::infinity();  // the lobe must keep its orientation
    return objective_.cubed_error(ltc::LtcDistribution(matrix(p), moments_.albedo));
  }
  void append_published_errors(std::vector<double>& out) const {
    if (!published_) {
      out.insert(out.end(), {nan, nan});
      return;
    }
    const auto theirs = judge_.errors(ltc::LtcDistribution(ltc::matrix_from_shader_form(published_->ltc1), moments_.albedo));
    out.insert(out.end(), {theirs.cubed, theirs.l2});
  }

  ltc::GgxTarget target_;
  double x_, r_;
  ltc::GgxMoments moments_;
  ltc::FitErrorEstimator objective_;
  ltc::FitErrorEstimator judge_;
  const ltc::PublishedLtcCell* published_;
};

std::vector<ModelOutput> ltc_outputs() {
  const std::string heitz = "Heitz et al. 2016 (published table)";
  return {
      {"error_cubed", "integral of |D - rho|^3 over the sphere, on the judge's finer lattice", "error"},
      {"error_l2", "sqrt(integral of (D - rho)^2) over the sphere, on the judge's finer lattice", "error"},
      {"published_error_cubed", "the published texel's cubed error, same judge and amplitude", "anchor_error", heitz,
       "error_cubed"},
      {"published_error_l2", "the published texel's L2 error, same judge and amplitude", "anchor_error", heitz,
       "error_l2"},
      {"norm", "albedo of the lobe: the LTC amplitude (published ltc_2.x)"},
      {"fresnel", "integral of rho (1 - v.h)^5: the Schlick Fresnel term (published ltc_2.y)"},
      {"matrix", "the forward matrix M, row-major (cosine directions to the lobe)", "output", "", "", 9},
      {"ltc_1", "texture 1 of the reference shaders: inverse of M over its middle entry, (m00, m20, m02, m22)",
       "output", "", "", 4, store::ValueType::f32},
      {"ltc_2", "texture 2 of the reference shaders: (norm, fresnel, 0, sphere form factor ratio)", "output", "", "",
       4, store::ValueType::f32},
  };
}

class LtcGgxProblem final : public SweepProblem {
 public:
  explicit LtcGgxProblem(LtcGgxSettings settings) : settings_(std::move(settings)) {}

  std::string description() const override {
    return "isotropic LTC fit of GGX (F = 1, height-correlated Smith), Heitz et al. 2016, on the published grid";
  }
  std::vector<ProblemAxis> axes() const override {
    using pbrfit::sweep::GridAxis;
    using pbrfit::sweep::Placement;
    return {{"sqrt_one_minus_cos", "x = sqrt(1 - cos theta_v); cos theta_v = cos(min(acos(1 - x^2), 1.57))", 0.0, 1.0,
             GridAxis{"sqrt_one_minus_cos", 0.0, 1.0, 64, Placement::edges}},
            {"roughness", "perceptual roughness r, alpha = max(r^2, 1e-5)", 0.0, 1.0,
             GridAxis{"roughness", 0.0, 1.0, 64, Placement::edges}}};
  }
  std::vector<ModelInfo> models() const override {
    using optimize::Transform;
    return {{"ltc",
             "M = [X Y Z] [[m00, 0, m02], [0, m11, 0], [m20, 0, 1]] in the frame of the lobe's average direction",
             {{"m00", 1e-6, 8.0, Transform::log},
              {"m11", 1e-6, 8.0, Transform::log},
              {"m02", -4.0, 4.0, Transform::linear},
              {"m20", -4.0, 4.0, Transform::linear}},
             "the fitting objective: integral of |D - rho|^3 over the sphere (MIS, objective lattice)",
             ltc_outputs()}};
  }
  std::map<std::string, std::string> attributes() const override {
    return {{"objective", "cubed error, MIS of GGX visible-normal and LTC samples, balance heuristic"},
            {"objective_points", std::to_string(settings_.objective_points) + " per strategy"},
            {"judge_points", std::to_string(settings_.metric_points) + " per strategy"},
            {"texture_layout", "ltc_1 and ltc_2 are [sqrt_one_minus_cos][roughness][rgba]: 64 x 64 RGBA textures "
                               "with roughness on the fast axis, as the reference shaders sample them"}};
  }
  std::unique_ptr<CellTarget> target(std::span<const double> c) const override {
    return std::make_unique<LtcCell>(c[0], c[1], settings_);
  }

 private:
  LtcGgxSettings settings_;
};

}  // namespace

std::unique_ptr<SweepProblem> make_ltc_ggx_problem(const LtcGgxSettings& settings) {
  return std::make_unique<LtcGgxProblem>(settings);
}

}  // namespace pbrfit::jobs::sweep
