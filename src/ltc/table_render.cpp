#include "pbrfit/ltc/table_render.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "pbrfit/ltc/distribution.hpp"

namespace pbrfit::ltc {
namespace {

constexpr double light_plane_y = 2.0;

}  // namespace

PlaneScene table_check_scene(std::size_t resolution) {
  PlaneScene s = camera_looking_at(Vector3(0.0, -2.0, 1.6), Vector3(0.0, 0.07, 0.0), Vector3::UnitZ(), resolution);
  s.tan_half_fov = 0.311;
  const double y = light_plane_y;
  s.light = {Vector3(-1.0, y, 0.2), Vector3(1.0, y, 0.2), Vector3(1.0, y, 1.2), Vector3(-1.0, y, 1.2)};
  return s;
}

std::optional<ShadingPoint> shading_point(const PlaneScene& scene, std::size_t column, std::size_t row) {
  const auto hit = scene.plane_hit(double(column) + 0.5, double(row) + 0.5);
  if (!hit) return std::nullopt;
  const Vector3 view = (scene.camera - *hit).normalized();
  // The shading frame: z the normal, x the view's direction along the plane (any, for a view along z).
  Frame frame;
  const Vector3 along(view.x(), view.y(), 0.0);
  if (along.norm() > 1e-12) {
    frame.x = along.normalized();
    frame.y = frame.z.cross(frame.x);
  }
  ShadingPoint point;
  point.cos_theta_view = std::clamp(view.z(), 0.0, 1.0);
  for (std::size_t i = 0; i < 4; ++i) point.light.vertices[i] = frame.to_local(scene.light[i] - *hit);
  const Vector3 light_normal = (scene.light[1] - scene.light[0]).cross(scene.light[2] - scene.light[0]);
  const Vector3 facing = scene.camera - scene.light[0];  // the side the light shines on
  point.lit = light_normal.dot(*hit - scene.light[0]) * light_normal.dot(facing) > 0.0;
  return point;
}

std::vector<double> render_plane(const PlaneScene& scene, std::size_t first_row, std::size_t rows,
                                 const std::function<double(const ShadingPoint&)>& shade) {
  const std::size_t n = scene.resolution;
  if (first_row + rows > n) throw std::invalid_argument("ltc: rows beyond the image");
  std::vector<double> image(rows * n, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t row = 0; row < rows; ++row)
    for (std::size_t column = 0; column < n; ++column)
      if (const auto point = shading_point(scene, column, first_row + row))
        image[row * n + column] = point->lit ? shade(*point) : 0.0;
  return image;
}

TableTexel interpolated_texel(std::span<const double> positions, std::span<const TableTexel> texels, double x) {
  if (positions.empty() || positions.size() != texels.size())
    throw std::invalid_argument("ltc: a table row needs as many texels as positions, at least one");
  if (x <= positions.front()) return texels.front();
  if (x >= positions.back()) return texels.back();
  const std::size_t above = std::size_t(std::upper_bound(positions.begin(), positions.end(), x) - positions.begin());
  const std::size_t below = above - 1;
  const double t = (x - positions[below]) / (positions[above] - positions[below]);
  TableTexel out;
  for (std::size_t k = 0; k < 4; ++k) out.ltc_1[k] = (1.0 - t) * texels[below].ltc_1[k] + t * texels[above].ltc_1[k];
  out.norm = (1.0 - t) * texels[below].norm + t * texels[above].norm;
  return out;
}

namespace {

// The texel's LTC, or nullopt with `value` set to what a shader would get without one (NaN or 0).
std::optional<LtcDistribution> texel_ltc(const TableTexel& texel, double& value) {
  value = std::numeric_limits<double>::quiet_NaN();
  for (double v : texel.ltc_1)
    if (!std::isfinite(v)) return std::nullopt;
  if (!std::isfinite(texel.norm)) return std::nullopt;
  value = 0.0;
  if (!(texel.norm > 0.0)) return std::nullopt;
  const Matrix3 inverse = inverse_from_shader_form(texel.ltc_1);
  if (!(std::abs(inverse.determinant()) > 1e-300)) return std::nullopt;
  return LtcDistribution(matrix_from_shader_form(texel.ltc_1), texel.norm);
}

}  // namespace

double table_shading(const TableTexel& texel, const Quad& light) {
  double value = 0.0;
  const auto ltc = texel_ltc(texel, value);
  return ltc ? ltc->integrate_polygon(light.vertices) : value;
}

double table_value(const TableTexel& texel, const Vector3& l) {
  double value = 0.0;
  const auto ltc = texel_ltc(texel, value);
  return ltc ? ltc->evaluate(l) : value;
}

double lobe_shading(const brdf::Lobe& lobe, const Quad& light) {
  const Vector3& v = lobe.view();
  const Vector3 peak = lobe.peak().value_or(Vector3(-v.x(), -v.y(), v.z()));
  const QuadIntegral integral = lobe_quad_integral(lobe, light, peak, ground_truth_accuracy);
  return integral.converged ? integral.value : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace pbrfit::ltc
