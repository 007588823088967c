#include "ltc_render.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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
  if (std::ranges::any_of(settings.models, [](const LtcModelSpec& m) { return bool(m.published); }))
    plan.layers.push_back({"published", "the published table read the same way (NaN for a model without one, or "
                                        "off its grid)"});
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
  if (with_published && spec.published && published_1 && published_2) {
    const auto theirs = texels(values, *published_1, *published_2);
    const auto published = ltc::render_plane(scene, first_row, rows, [&](const ltc::ShadingPoint& point) {
      return ltc::table_shading(ltc::interpolated_texel(positions, theirs, std::sqrt(1.0 - point.cos_theta_view)),
                                point.light);
    });
    out.insert(out.end(), published.begin(), published.end());
  } else if (with_published) {
    out.insert(out.end(), reference.size(), std::numeric_limits<double>::quiet_NaN());
  }
  return out;
}

}  // namespace pbrfit::jobs::sweep
