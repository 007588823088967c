// The result layout of an `ebrdf` job (docs/results-ebrdf.md).
#include <cstdio>

#include "pbrfit/ebrdf/footprint_samples.hpp"
#include "pbrfit/jobs/ebrdf/ebrdf_workload.hpp"

namespace pbrfit::jobs::ebrdf {
namespace {

namespace eb = pbrfit::ebrdf;

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

// A number that reads back exactly (17 significant digits).
std::string exact(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

std::vector<double> texel_centres(std::size_t side) {
  std::vector<double> uv(side);
  for (std::size_t i = 0; i < side; ++i) uv[i] = (double(i) + 0.5) / double(side);
  return uv;
}

std::vector<double> indices(std::size_t n) {
  std::vector<double> out(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = double(i);
  return out;
}

store::Group normal_map_group(const EbrdfSettings& s) {
  store::Group g;
  g.name = "ebrdf/normal_map";
  g.description = "the MIP-0 tangent-space normals the tables filter (unit vectors, z >= 0.01)";
  g.attributes = {{"source", s.map_source}, {"size", std::to_string(s.map->size())}};
  const std::size_t n = s.map->size();
  g.axes = {{"v", texel_centres(n), "texel centre, (row + 0.5) / size"},
            {"u", texel_centres(n), "texel centre, (column + 0.5) / size"},
            {"xyz", indices(3), "normal component x, y, z"}};
  g.tables = {{"normal", {"v", "u", "xyz"}, "unit normal of each texel", store::ValueType::f32}};
  return g;
}

store::Group level_group_layout(const EbrdfSettings& s, const ComponentSettings& c, std::size_t level) {
  const std::size_t side = eb::mip_side(s.map->size(), level);
  const std::size_t tile = std::min(s.tile, side);
  std::vector<double> thetas, phis;
  for (std::size_t i = 0; i < c.views.n_theta; ++i) thetas.push_back(c.views.theta(i));
  for (std::size_t j = 0; j < c.views.n_phi; ++j) phis.push_back(c.views.phi(j));
  store::Group g;
  g.name = level_group(c, level);
  g.description = std::string("LTCs of the ") + component_name(c.component) + " effective BRDF of mip level " +
                  std::to_string(level) + ": each texel filters a " + std::to_string(1u << level) + " x " +
                  std::to_string(1u << level) + " footprint of MIP-0 texels";
  g.attributes = {{"component", component_name(c.component)},
                  {"level", std::to_string(level)},
                  {"base_brdf", c.component == eb::Component::specular
                                    ? "the LTC of GGX (alpha = " + number(s.roughness * s.roughness) +
                                          ", F = 1, height-correlated Smith) at each texel's view elevation, as MIP-0 shading uses it"
                                    : std::string("Lambert")},
                  {"view_interpolation", c.component == eb::Component::specular
                                             ? "in the mirror frame: interpolate R(theta_i)^T M over the views, then apply "
                                               "R(theta), R the turn about y taking z to (-sin theta, 0, cos theta)"
                                             : std::string("linear in M")},
                  {"alpha", c.component == eb::Component::specular ? exact(s.roughness * s.roughness) : "none"},
                  {"samples_per_ebrdf", std::to_string(s.samples)},
                  {"fit", fit_method_name(s.fit.method)},
                  {"frame", "geometric frame rotated so that the view azimuth is 0: x towards the view's azimuth, "
                            "z the geometric normal"},
                  {"matrix", "row-major M (9 entries) of D(w) = amplitude D_o(M^-1 w / |M^-1 w|) |det M^-1| / "
                             "|M^-1 w|^3, aligned (Kt et al. 2022) and scaled to |det M| = 1"}};
  g.axes = {{"v", texel_centres(side), "mip texel centre, (row + 0.5) / side"},
            {"u", texel_centres(side), "mip texel centre, (column + 0.5) / side"},
            {"theta", thetas, "view elevation from the geometric normal, radians: 0.999 pi/2 sin(i / (n - 1) pi/2)"},
            {"phi", phis, "view azimuth in the tangent plane (0 = +u), radians"},
            {"entry", indices(9), "matrix entry, row-major: m00 m01 m02 m10 ... m22"}};
  const std::vector<std::string> views = {"v", "u", "theta", "phi"};
  const std::vector<std::uint64_t> chunk = {tile, tile, c.views.n_theta, c.views.n_phi};
  store::Table matrix{"matrix", {"v", "u", "theta", "phi", "entry"}, "LTC matrix M per texel and view",
                      store::ValueType::f32};
  matrix.chunk = {tile, tile, c.views.n_theta, c.views.n_phi, 9};
  store::Table amplitude{"amplitude", views, "LTC amplitude: the footprint's mean directional albedo (F = 1)",
                         store::ValueType::f32};
  amplitude.chunk = chunk;
  store::Table error{"error", views, "sliced Wasserstein distance between the LTC and the eBRDF samples (" +
                                         std::to_string(s.fit.error_axes) + " fixed axes)",
                     store::ValueType::f32};
  error.chunk = chunk;
  g.tables = {matrix, amplitude, error};
  return g;
}

}  // namespace

store::ResultLayout EbrdfWorkload::layout() const {
  store::ResultLayout layout;
  layout.groups.push_back(normal_map_group(settings_));
  for (const auto& c : settings_.components)
    for (std::size_t level = 1; level <= settings_.max_level; ++level)
      layout.groups.push_back(level_group_layout(settings_, c, level));
  return layout;
}

}  // namespace pbrfit::jobs::ebrdf
