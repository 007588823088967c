#include "ltc_render.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "pbrfit/core/error.hpp"
#include "pbrfit/ltc/table_render.hpp"

namespace pbrfit::jobs::sweep {
namespace {

// The index of the grid value nearest `value` on axis d.
std::size_t nearest(const pbrfit::sweep::LevelGrid& grid, std::size_t d, double value) {
  const auto values = grid.axes()[d].values();
  std::size_t best = 0;
  for (std::size_t i = 1; i < values.size(); ++i)
    if (std::abs(values[i] - value) < std::abs(values[best] - value)) best = i;
  return best;
}

// Where output `name` starts among a model's output values.
std::optional<std::size_t> offset_of(const std::vector<ModelOutput>& outputs, const std::string& name) {
  std::size_t offset = 0;
  for (const auto& output : outputs) {
    if (output.name == name) return offset;
    offset += output.components;
  }
  return std::nullopt;
}

// The table's texels along the image's row of cells, read from ltc_1 and the first component of ltc_2.
std::vector<ltc::TableTexel> texels(std::span<const std::vector<double>> values, std::size_t ltc_1, std::size_t ltc_2) {
  std::vector<ltc::TableTexel> out;
  for (const auto& v : values) {
    ltc::TableTexel texel;
    for (std::size_t k = 0; k < 4; ++k) texel.ltc_1[k] = v.at(ltc_1 + k);
    texel.norm = v.at(ltc_2);
    out.push_back(texel);
  }
  return out;
}

constexpr double degree = std::numbers::pi / 180.0;

// The view angle of the view axis value x, in degrees.
double view_degrees(double x) { return std::acos(ltc_cos_theta(x)) / degree; }

// The lobes in the plane of incidence at the grid's views nearest 30 and 70 degrees, at every degree of the
// light from -90 (the mirror side) to 90 (the view's side).
RenderCurves lobe_curves(const pbrfit::sweep::LevelGrid& grid, std::size_t view, bool published) {
  RenderCurves c;
  c.group = "lobes";
  c.description = "the fitted lobe beside its target in the plane of incidence, at each image's roughness and the "
                  "grid's views nearest 30 and 70 degrees: rho(l) = f(v, l) cos theta_l with F = 1, and norm x "
                  "the LTC at the cell (docs/results-sweep.md)";
  c.set_axis = "view_degrees";
  c.set_description = "theta_v of the cell's view, in degrees";
  for (double wanted : {30.0, 70.0}) {
    double best = 0.0, distance = std::numeric_limits<double>::infinity();
    for (double x : grid.axes()[view].values())
      if (std::abs(view_degrees(x) - wanted) < distance) best = view_degrees(x), distance = std::abs(best - wanted);
    if (std::ranges::find(c.sets, best) == c.sets.end()) c.sets.push_back(best);
  }
  c.position_axis = "light_degrees";
  c.position_description = "the light's angle from the normal in the plane of incidence, in degrees: l = (sin t, 0, "
                           "cos t), the view at positive angles, its mirror at negative ones";
  for (int t = -90; t <= 90; ++t) c.positions.push_back(double(t));
  c.layers = {{"target", "the lobe fitted: rho(l) = f(v, l) cos theta_l, F = 1"},
              {"ltc", "the table's texel at the cell: norm x the LTC's value at l"}};
  if (published) c.layers.push_back({"published", "the published texel's, where the cell is on its grid (else NaN)"});
  return c;
}

// The image's curves: for each set (view), each layer over the positions.
std::vector<double> lobe_values(const LtcModelSpec& spec, const RenderCurves& curves,
                                const std::vector<std::vector<double>>& coordinates, std::size_t view,
                                const std::vector<ltc::TableTexel>& ours, const std::vector<ltc::TableTexel>* theirs) {
  const std::size_t n = curves.positions.size();
  std::vector<double> out(curves.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t s = 0; s < curves.sets.size(); ++s) {
    std::size_t cell = 0;
    for (std::size_t k = 1; k < coordinates.size(); ++k)
      if (std::abs(view_degrees(coordinates[k][view]) - curves.sets[s]) <
          std::abs(view_degrees(coordinates[cell][view]) - curves.sets[s]))
        cell = k;
    const auto lobe = spec.lobe(coordinates[cell]);
    const auto at = [&](std::size_t layer, std::size_t i) -> double& {
      return out[(layer * curves.sets.size() + s) * n + i];
    };
    for (std::size_t i = 0; i < n; ++i) {
      const double t = curves.positions[i] * degree;
      const Vector3 l(std::sin(t), 0.0, std::cos(t));
      at(0, i) = lobe->value(l);
      at(1, i) = ltc::table_value(ours[cell], l);
      if (theirs) at(2, i) = ltc::table_value((*theirs)[cell], l);
    }
  }
  return out;
}

}  // namespace

std::optional<RenderPlan> ltc_render_plan(const LtcProblemSettings& settings, const pbrfit::sweep::LevelGrid& grid,
                                          std::size_t view, std::optional<std::size_t> roughness) {
  if (settings.render_size == 0) return std::nullopt;
  RenderPlan plan;
  plan.description =
      "the plane z = 0 under a one-sided rectangle light of radiance 1 (2 x 1, upright on y = 2, z from 0.2 to 1.2, "
      "facing the camera), seen from (0, -2, 1.6) towards (0, 0.07, 0) with a vertical field of view of 2 "
      "atan(0.311), views from 35 to 70 degrees off the normal; F = 1; 0 behind the light (ltc/table_render.hpp)";
  plan.resolution = settings.render_size;
  plan.layers = {{"ltc", "the table as a shader reads it (ltc_1 and norm filtered linearly along the view): norm x "
                         "the LTC's integral over the light"},
                 {"reference", "ground truth: the integral of the cosine-weighted lobe over the light (adaptive "
                               "cubature, ltc/table_render.hpp; NaN where it does not converge)"}};
  const bool published =
      std::ranges::any_of(settings.models, [](const LtcModelSpec& m) { return bool(m.published); });
  if (published)
    plan.layers.push_back({"published", "the published table read the same way (NaN for a model without one, or "
                                        "off its grid)"});
  plan.curves = lobe_curves(grid, view, published);
  std::vector<std::size_t> fixed(grid.dimension());
  for (std::size_t d = 0; d < grid.dimension(); ++d) fixed[d] = grid.axes()[d].count / 2;
  std::vector<std::size_t> picks;
  if (roughness) {
    plan.image_axis = grid.axes()[*roughness].name;
    plan.image_axis_description = "the table's roughness each image is rendered at (the grid value nearest 0.25, "
                                  "0.5 and 0.75)";
    for (double r : {0.25, 0.5, 0.75}) {
      const std::size_t i = nearest(grid, *roughness, r);
      if (std::ranges::find(picks, i) == picks.end()) picks.push_back(i);
    }
  } else {
    plan.image_axis = "table";
    plan.image_axis_description = "the one image of a table without a roughness axis";
    picks.push_back(0);
  }
  for (std::size_t pick : picks) {
    auto at = fixed;
    if (roughness) at[*roughness] = pick;
    std::vector<std::size_t> cells;
    std::vector<std::vector<double>> coordinates;
    for (std::size_t i = 0; i < grid.axes()[view].count; ++i) {
      at[view] = i;
      cells.push_back(grid.flat_index(at));
      coordinates.push_back(grid.coordinates(cells.back()));
    }
    plan.image_values.push_back(roughness ? grid.axes()[*roughness].values()[pick] : 0.0);
    plan.cells.push_back(std::move(cells));
    plan.coordinates.push_back(std::move(coordinates));
  }
  return plan;
}

std::vector<double> ltc_render(const LtcModelSpec& spec, const std::vector<ModelOutput>& outputs,
                               const RenderPlan& plan, std::size_t image, std::size_t first_row, std::size_t rows,
                               std::size_t view, std::span<const std::vector<double>> values) {
  const bool with_published = plan.layers.size() == 3;
  const auto& coordinates = plan.coordinates.at(image);
  if (values.size() != coordinates.size()) throw RunError("sweep: an LTC render without its row of cells");
  std::vector<double> positions;
  for (const auto& c : coordinates) positions.push_back(c[view]);
  const auto ltc_1 = offset_of(outputs, "ltc_1"), ltc_2 = offset_of(outputs, "ltc_2");
  if (!ltc_1 || !ltc_2) throw RunError("sweep: an LTC model without its ltc_1 and ltc_2 outputs");
  const auto ours = texels(values, *ltc_1, *ltc_2);
  const ltc::PlaneScene scene = ltc::table_check_scene(plan.resolution);

  std::vector<double> out = ltc::render_plane(scene, first_row, rows, [&](const ltc::ShadingPoint& point) {
    return ltc::table_shading(ltc::interpolated_texel(positions, ours, std::sqrt(1.0 - point.cos_theta_view)),
                              point.light);
  });
  const auto reference = ltc::render_plane(scene, first_row, rows, [&](const ltc::ShadingPoint& point) {
    auto c = coordinates.front();
    c[view] = std::sqrt(1.0 - point.cos_theta_view);
    return ltc::lobe_shading(*spec.lobe(c), point.light);
  });
  out.insert(out.end(), reference.begin(), reference.end());
  const auto published_1 = offset_of(outputs, "published_ltc_1"), published_2 = offset_of(outputs, "published_ltc_2");
  std::vector<ltc::TableTexel> theirs;
  if (with_published && spec.published && published_1 && published_2) {
    theirs = texels(values, *published_1, *published_2);
    const auto published = ltc::render_plane(scene, first_row, rows, [&](const ltc::ShadingPoint& point) {
      return ltc::table_shading(ltc::interpolated_texel(positions, theirs, std::sqrt(1.0 - point.cos_theta_view)),
                                point.light);
    });
    out.insert(out.end(), published.begin(), published.end());
  } else if (with_published) {
    out.insert(out.end(), reference.size(), std::numeric_limits<double>::quiet_NaN());
  }
  if (first_row == 0 && plan.curves) {
    const auto curves = lobe_values(spec, *plan.curves, coordinates, view, ours, theirs.empty() ? nullptr : &theirs);
    out.insert(out.end(), curves.begin(), curves.end());
  }
  return out;
}

}  // namespace pbrfit::jobs::sweep
