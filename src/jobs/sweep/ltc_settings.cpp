// Problems `ltc` and `ltc_ggx` from a job file (ltc_problem.hpp): which lobes are fitted (the built-in BRDF
// families, a BRDF written as an expression, or a measured material), the axes an expression adds, and the
// objective's keys.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "pbrfit/brdf/brdf_families.hpp"
#include "pbrfit/brdf/direction_inputs.hpp"
#include "pbrfit/brdf/merl_table.hpp"
#include "pbrfit/brdf/tabulated_lobe.hpp"
#include "pbrfit/core/error.hpp"
#include "pbrfit/store/share_directory.hpp"
#include "pbrfit/gp/tree_walker.hpp"
#include "pbrfit/jobs/brdf/material_sets.hpp"
#include "pbrfit/jobs/brdf/material_source.hpp"
#include "pbrfit/jobs/sweep/ltc_problem.hpp"
#include "pbrfit/jobs/sweep/problem_catalogue.hpp"
#include "pbrfit/ltc/point_sets.hpp"
#include "pbrfit/store/atomic_file.hpp"

namespace pbrfit::jobs::sweep {
namespace {

constexpr const char* view_axis = "sqrt_one_minus_cos";
constexpr const char* roughness_axis = "roughness";

// The published table the GGX anchors compare with; null when the data file is not there.
std::shared_ptr<const ltc::PublishedLtcTable> published_ltc_table() {
  static const std::shared_ptr<const ltc::PublishedLtcTable> table = []() -> std::shared_ptr<const ltc::PublishedLtcTable> {
    const std::string path = store::data_directory() + "/reference/ltc_ggx_heitz2016_64.csv";
    try {
      const Bytes bytes = store::read_whole_file(path, 4u << 20);
      const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
      return std::make_shared<const ltc::PublishedLtcTable>(ltc::parse_published_ltc_table(text));
    } catch (const InputError&) {
      return nullptr;
    } catch (const std::invalid_argument& e) {
      throw RunError(path + ": " + e.what());
    }
  }();
  return table;
}

LtcProblemSettings objective_settings(const ObjectiveKeys& objective) {
  LtcProblemSettings s;
  s.objective_points = objective.samples.value_or(s.objective_points);
  s.metric_points = objective.judge_samples.value_or(s.metric_points);
  s.polygon_quads = objective.polygon_quads.value_or(s.polygon_quads);
  s.polygon.relative_tolerance = objective.polygon_tolerance.value_or(s.polygon.relative_tolerance);
  s.render_size = objective.render_size.value_or(s.render_size);
  if (objective.fit_to_lights.value) {
    if (s.polygon_quads == 0) objective.fit_to_lights.reject("is 'lights', which needs 'polygon_quads' > 0 to judge the fit");
    s.fit_to = LtcProblemSettings::FitTo::lights;
    if (objective.training_quads.written) s.training_quads = objective.training_quads.value;
  } else if (objective.training_quads.written) {
    objective.training_quads.reject("is read with 'fit_to: lights' only");
  }
  return s;
}

LtcModelSpec family_model(pbrfit::brdf::BrdfFamily family) {
  const pbrfit::brdf::BrdfFamilyInfo& info = pbrfit::brdf::family_info(family);
  LtcModelSpec spec;
  spec.name = std::string(info.name);
  spec.description = std::string(info.description) + "; " + std::string(info.parameter);
  spec.lobe = [family](std::span<const double> c) -> std::shared_ptr<const pbrfit::brdf::Lobe> {
    return pbrfit::brdf::make_family_lobe(family, c[1], ltc_cos_theta(c[0]));
  };
  if (family == pbrfit::brdf::BrdfFamily::ggx) spec.published = published_ltc_table();
  return spec;
}

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

// A BRDF f(l, v) written as an expression of the direction inputs, pi, the roughness and further axes.
struct ExpressionBrdf {
  gp::Program program;
  std::vector<std::string> axis_names;  // the row's names after the directions and pi

  static std::vector<std::string> names(const std::vector<std::string>& axes) {
    std::vector<std::string> out = pbrfit::brdf::direction_input_names();
    out.push_back("pi");
    out.insert(out.end(), axes.begin(), axes.end());
    return out;
  }

  // f for light l and view v (both above the horizon) at the axis values.
  double value(const Vector3& l, const Vector3& v, std::span<const double> axes) const {
    const auto directions = pbrfit::brdf::direction_inputs(l, v);
    double row[pbrfit::brdf::direction_input_count + 1 + 16];
    std::copy(directions.begin(), directions.end(), row);
    row[pbrfit::brdf::direction_input_count] = std::numbers::pi;
    std::copy(axes.begin(), axes.end(), row + pbrfit::brdf::direction_input_count + 1);
    return gp::walk_tree<double>(program, std::span<const double>(row, pbrfit::brdf::direction_input_count + 1 + axes.size()));
  }

  std::string where(const Vector3& l, const Vector3& v, std::span<const double> axes) const {
    const auto d = pbrfit::brdf::direction_inputs(l, v);
    std::string text = "nl = " + number_text(d[0]) + ", nv = " + number_text(d[1]) + ", lv = " + number_text(d[4]);
    for (std::size_t k = 0; k < axes.size(); ++k) text += ", " + axis_names[k] + " = " + number_text(axes[k]);
    return text;
  }
};

// The expression's axes besides the view: the roughness, then those the job adds (each with from, to, count).
std::vector<ProblemAxis> further_axes(const SweepKeys& sweep) {
  std::vector<ProblemAxis> out;
  for (const AxisKeys& item : sweep.axes.value) {
    const std::string& name = item.name.value;
    if (name == view_axis || name == roughness_axis) continue;
    const auto require = [&](const auto& key) {
      if (!key.written)
        key.reject("is required for an axis the BRDF expression adds ('" + name + "' is not " + view_axis + " or " +
                   roughness_axis + ")");
    };
    require(item.from), require(item.to), require(item.count);
    if (name == "pi" || std::ranges::find(pbrfit::brdf::direction_input_names(), name) != pbrfit::brdf::direction_input_names().end())
      item.name.reject("is '" + name + "', which the expression already reads as a direction input");
    pbrfit::sweep::GridAxis axis{name, item.from.value, item.to.value, std::size_t(item.count.value), item.samples.value};
    out.push_back({name, "axis " + name + " of the BRDF expression", -HUGE_VAL, HUGE_VAL, axis});
  }
  return out;
}

// The end values of an axis as the job sets it (or the default).
std::vector<double> axis_ends(const SweepKeys& sweep, const std::string& name, double from, double to) {
  for (const AxisKeys& item : sweep.axes.value)
    if (item.name.value == name)
      return {item.from.written ? item.from.value : from, item.to.written ? item.to.value : to};
  return {from, to};
}

// Refuses an expression that is negative or not finite anywhere on a probe of views, lights and the axes'
// end values: a BRDF is a non-negative number wherever both directions are above the horizon.
void check_expression(const spec::Located<std::string>& text, const ExpressionBrdf& f,
                      const std::vector<std::vector<double>>& ends) {
  std::vector<double> axes(ends.size());
  const auto check_at = [&](const Vector3& l, const Vector3& v) {
    const double value = f.value(l, v, axes);
    if (!std::isfinite(value)) text.reject("is not a finite number at " + f.where(l, v, axes));
    if (value < 0.0) text.reject("is negative (" + number_text(value) + ") at " + f.where(l, v, axes));
  };
  const std::size_t corners = std::size_t(1) << ends.size();
  for (std::size_t corner = 0; corner < corners; ++corner) {
    for (std::size_t k = 0; k < ends.size(); ++k) axes[k] = ends[k][(corner >> k) & 1];
    for (double cos_v : {1.0, 0.8, 0.5, 0.2, 0.02}) {
      const Vector3 v(std::sqrt(1.0 - cos_v * cos_v), 0.0, cos_v);
      for (int i = 0; i < 12; ++i) {
        const double z = 1.0 - (i + 0.5) / 12.0;
        const double radius = std::sqrt(1.0 - z * z);
        for (int j = 0; j < 24; ++j) {
          const double phi = 2.0 * std::numbers::pi * (j + 0.5) / 24.0;
          check_at(Vector3(radius * std::cos(phi), radius * std::sin(phi), z), v);
        }
      }
    }
  }
}

LtcModelSpec expression_model(const SweepKeys& sweep, const BrdfKeys& brdf, LtcProblemSettings& s) {
  s.extra_axes = further_axes(sweep);
  if (s.extra_axes.size() > 8) sweep.axes.reject("adds more than 8 axes to the BRDF expression");
  auto f = std::make_shared<ExpressionBrdf>();
  f->axis_names = {roughness_axis};
  for (const auto& axis : s.extra_axes) f->axis_names.push_back(axis.name);
  f->program = parse_expression_at(brdf.expression, {ExpressionBrdf::names(f->axis_names), {}}).program;
  std::vector<std::vector<double>> ends = {axis_ends(sweep, roughness_axis, 0.0, 1.0)};
  for (const auto& axis : s.extra_axes) ends.push_back({axis.default_axis.lower, axis.default_axis.upper});
  check_expression(brdf.expression, *f, ends);
  s.roughness_description = "roughness r in [0, 1], read by the BRDF expression as 'roughness'";
  s.attributes["brdf_expression"] = brdf.expression.value;
  const std::size_t extras = s.extra_axes.size();
  LtcModelSpec spec;
  spec.name = brdf.name.value_or("expression");
  spec.description = "f(l, v) = " + brdf.expression.value + ", times n.l";
  spec.lobe = [f, extras](std::span<const double> c) -> std::shared_ptr<const pbrfit::brdf::Lobe> {
    // c = (extra axes..., x, roughness); the expression's axis row is (roughness, extra axes...).
    std::vector<double> axes = {c[extras + 1]};
    axes.insert(axes.end(), c.begin(), c.begin() + std::ptrdiff_t(extras));
    const double cos_v = ltc_cos_theta(c[extras]);
    const Vector3 v = pbrfit::brdf::view_in_xz_plane(cos_v);
    auto rho = [f, axes, v](const Vector3& l) {
      if (!(l.z() > 0.0)) return 0.0;
      const double value = f->value(l, v, axes);
      if (!std::isfinite(value)) throw RunError("sweep: the BRDF expression is not a finite number at " + f->where(l, v, axes));
      return std::max(0.0, value) * l.z();
    };
    return std::make_shared<pbrfit::brdf::TabulatedLobe>(cos_v, std::move(rho));
  };
  return spec;
}

constexpr double luminance_weights[3] = {0.2126, 0.7152, 0.0722};  // linear Rec. 709

LtcModelSpec material_model(const BrdfKeys& brdf, LtcProblemSettings& s) {
  const std::string& name = brdf.material.value;
  jobs::brdf::MaterialSource source;
  if (brdf.merl_directory.written) source.merl_directory = brdf.merl_directory.value;
  source.cache_directory = brdf.cache.value;
  auto table = std::make_shared<const pbrfit::brdf::MerlTable>(jobs::brdf::load_material(name, source));
  s.roughness_axis = false;
  s.attributes["material"] = name;
  s.attributes["material_file"] = jobs::brdf::material_path(name, source);
  s.attributes["material_luminance"] = "rho = (0.2126 R + 0.7152 G + 0.0722 B) (n.l), trilinear in the MERL grid";
  const auto rgb = [table](const Vector3& l, const Vector3& v) {
    auto value = table->interpolate(l, v);
    for (double& c : value)
      if (std::isnan(c)) c = 0.0;
    return value;
  };
  LtcModelSpec spec;
  spec.name = brdf.name.value_or(name);
  spec.description = "measured material " + name + " (luminance)";
  spec.lobe = [rgb](std::span<const double> c) -> std::shared_ptr<const pbrfit::brdf::Lobe> {
    const double cos_v = ltc_cos_theta(c[0]);
    const Vector3 v = pbrfit::brdf::view_in_xz_plane(cos_v);
    auto rho = [rgb, v](const Vector3& l) {
      if (!(l.z() > 0.0)) return 0.0;
      const auto value = rgb(l, v);
      return (luminance_weights[0] * value[0] + luminance_weights[1] * value[1] + luminance_weights[2] * value[2]) *
             l.z();
    };
    return std::make_shared<pbrfit::brdf::TabulatedLobe>(cos_v, std::move(rho));
  };
  spec.extra_outputs = {{"norm_rgb", "the albedo of each colour channel (the LTC norm is their luminance)", "output",
                         "", "", 3}};
  const std::size_t points = s.moment_points;
  spec.extra_values = [rgb, points](const pbrfit::brdf::Lobe& lobe, std::span<const double>) {
    std::array<double, 3> sum{};
    for (const auto& [u1, u2] : ltc::golden_lattice(points)) {
      const Vector3 l = lobe.sample(u1, u2);
      if (!(l.z() > 0.0)) continue;
      const double pdf = lobe.evaluate(l).pdf;
      if (!(pdf > 0.0)) continue;
      const auto value = rgb(l, lobe.view());
      for (int c = 0; c < 3; ++c) sum[c] += value[c] * l.z() / pdf;
    }
    return std::vector<double>{sum[0] / double(points), sum[1] / double(points), sum[2] / double(points)};
  };
  return spec;
}

}  // namespace

spec::Keys<BrdfKeys> brdf_keys() {
  spec::Keys<BrdfKeys> k("brdf");
  k.string("expression", "a BRDF f(l, v) of nl, nv, nh, vh, lv, rv, hr, lr, pi, roughness and the axes the job adds",
           &BrdfKeys::expression);
  k.choice("material", jobs::brdf::merl_material_names(), "a MERL material: its .binary file or its neural stand-in",
           &BrdfKeys::material);
  k.string("merl_directory", "where the MERL .binary files are (default: the neural stand-ins of data/merl_nbrdf)",
           &BrdfKeys::merl_directory);
  k.string("cache", "where the stand-in evaluated on the MERL grid is kept as a .binary file ('' for none)",
           &BrdfKeys::cache)
      .defaults_to(std::string(jobs::brdf::default_material_cache));
  k.string("name", "the table's model and result group (default: 'expression', or the material's name)",
           &BrdfKeys::name);
  return k;
}

std::unique_ptr<SweepProblem> make_ltc(const SweepKeys& sweep) {
  LtcProblemSettings s = objective_settings(sweep.objective);
  s.description = "isotropic LTC tables (Heitz et al. 2016) of chosen BRDF lobes, F = 1";
  if (!sweep.brdf.written) {
    for (const auto& family : pbrfit::brdf::brdf_families()) s.models.push_back(family_model(family.family));
    return make_ltc_problem(std::move(s));
  }
  const BrdfKeys& brdf = sweep.brdf.value;
  if (brdf.expression.written == brdf.material.written)
    sweep.brdf.reject("needs either 'expression' (a BRDF written out) or 'material' (a MERL material), not both");
  if (brdf.merl_directory.written && !brdf.material.written) brdf.merl_directory.reject("applies to 'material' only");
  if (brdf.cache.written && !brdf.material.written) brdf.cache.reject("applies to 'material' only");
  if (sweep.models.written) sweep.models.reject("does not apply to a 'brdf' section (it makes one model)");
  s.models.push_back(brdf.expression.written ? expression_model(sweep, brdf, s) : material_model(brdf, s));
  return make_ltc_problem(std::move(s));
}

std::unique_ptr<SweepProblem> make_ltc_ggx(const SweepKeys& sweep) {
  LtcProblemSettings s = objective_settings(sweep.objective);
  s.description = "isotropic LTC fit of GGX (F = 1, height-correlated Smith), Heitz et al. 2016, on the published grid";
  s.roughness_description = "perceptual roughness r, alpha = max(r^2, 1e-5)";
  LtcModelSpec ggx = family_model(pbrfit::brdf::BrdfFamily::ggx);
  ggx.name = "ltc";
  s.models.push_back(std::move(ggx));
  return make_ltc_problem(std::move(s));
}

}  // namespace pbrfit::jobs::sweep
