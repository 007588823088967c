#include "pbrfit/ltc/polygon_lighting.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "fan_points.hpp"
#include "pbrfit/core/kernel_set.hpp"
#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/integrate/adaptive_cubature.hpp"
#include "pbrfit/integrate/gauss_kronrod.hpp"
#include "polygon_clipping.hpp"

namespace pbrfit::ltc {
namespace {

constexpr double degree = std::numbers::pi / 180.0;

// Any unit vector perpendicular to a unit w.
Vector3 perpendicular(const Vector3& w) { return Frame::from_z(w).x; }

Vector3 rotated(const Vector3& w, const Vector3& axis, double angle) {
  return w * std::cos(angle) + axis.cross(w) * std::sin(angle) + axis * axis.dot(w) * (1.0 - std::cos(angle));
}

// The quad's polygon above the plane z = 0 (Sutherland-Hodgman), 0 to 5 vertices.
std::vector<Vector3> clipped_to_horizon(const Quad& quad) {
  std::vector<Vector3> out;
  Vector3 previous = quad.vertices[3];
  for (const Vector3& current : quad.vertices) {
    const bool previous_above = previous.z() >= 0.0, current_above = current.z() >= 0.0;
    if (previous_above != current_above) out.push_back(detail::horizon_crossing(previous, current));
    if (current_above) out.push_back(current);
    previous = current;
  }
  return out;
}

// The point of a convex planar polygon closest to where the ray through `peak` meets its plane.
Vector3 fan_apex(const std::vector<Vector3>& polygon, const Vector3& normal, const Vector3& peak) {
  const double height = normal.dot(polygon[0]);  // signed distance of the plane from the origin
  const double along = normal.dot(peak);
  if (!(along * height > 0.0)) {
    // The ray misses the plane: the vertex seen closest to the peak.
    return *std::max_element(polygon.begin(), polygon.end(), [&](const Vector3& a, const Vector3& b) {
      return a.normalized().dot(peak) < b.normalized().dot(peak);
    });
  }
  const Vector3 hit = peak * (height / along);
  bool inside = true;
  const std::size_t n = polygon.size();
  const double orientation = normal.dot((polygon[1] - polygon[0]).cross(polygon[2] - polygon[0])) >= 0.0 ? 1.0 : -1.0;
  for (std::size_t i = 0; i < n && inside; ++i) {
    const Vector3& a = polygon[i];
    const Vector3& b = polygon[(i + 1) % n];
    inside = orientation * normal.dot((b - a).cross(hit - a)) >= 0.0;
  }
  if (inside) return hit;
  Vector3 best = polygon[0];
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    const Vector3& a = polygon[i];
    const Vector3 edge = polygon[(i + 1) % n] - a;
    const double t = std::clamp((hit - a).dot(edge) / edge.squaredNorm(), 0.0, 1.0);
    const Vector3 point = a + t * edge;
    const double distance = (point - hit).squaredNorm();
    if (distance < best_distance) best_distance = distance, best = point;
  }
  return best;
}

// The solid angle of the triangle (a, b, c) seen from the origin (Van Oosterom & Strackee 1983).
double triangle_solid_angle(const Vector3& a, const Vector3& b, const Vector3& c) {
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double numerator = std::abs(a.dot(b.cross(c)));
  const double denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
  return 2.0 * std::atan2(numerator, denominator);
}

struct FanTriangle {
  Vector3 apex, from, edge;  // the edge runs from `from` to `from + edge`
  double double_area = 0.0;
};

// The lobe over the fan's triangles: triangle k occupies [k, k + 1] x [0, 1] of (s, tau), tiles never
// straddle two. A point is apex + tau^4 (from + s edge - apex), so that the integrand stays smooth where
// the lobe's peak sits at the apex. A whole Gauss-Kronrod line of tau reaches the lobe at once
// (Lobe::value_many, integrate/outer_binding.hpp), with the same values as one point at a time.
class FanIntegrand {
 public:
  FanIntegrand(const brdf::Lobe& lobe, const std::vector<FanTriangle>& triangles, const Vector3& normal)
      : lobe_(lobe), triangles_(triangles), normal_(normal) {}

  std::array<double, 1> operator()(const std::array<double, 2>& x) const {
    std::array<double, 1> value{};
    points(x[0], &x[1], 1, value.data());
    return value;
  }

  void line(const std::array<double, 2>& x, const double* tau, double* out) const {
    points(x[0], tau, line_points, out);
  }

 private:
  static constexpr std::size_t line_points = integrate::gauss_kronrod::kronrod_size;
  static_assert(line_points <= detail::fan_line_points);

  void points(double s_of_fan, const double* tau, std::size_t n, double* out) const {
    const std::size_t k = std::min(triangles_.size() - 1, static_cast<std::size_t>(s_of_fan));
    const FanTriangle& t = triangles_[k];
    const detail::FanLine line{t.apex, t.from, t.edge, normal_, t.double_area, s_of_fan - double(k)};
    std::array<Vector3, line_points> directions;
    std::array<double, line_points> solid_angle, jacobian, value;
    detail::fan_points(active_kernel_set())(line, tau, n, directions.data(), solid_angle.data(), jacobian.data());
    lobe_.value_many(std::span(directions.data(), n), std::span(value.data(), n));
    for (std::size_t i = 0; i < n; ++i) out[i] = value[i] * solid_angle[i] * jacobian[i];
  }

  const brdf::Lobe& lobe_;
  const std::vector<FanTriangle>& triangles_;
  Vector3 normal_;
};

}  // namespace

std::vector<Quad> random_quads(std::size_t count, std::uint64_t seed) {
  std::vector<Quad> quads;
  quads.reserve(count);
  for (std::size_t k = 0; k < count; ++k) {
    RandomStream random(seed, k);
    const double size = std::exp(std::log(1.0 * degree) + random.uniform() * std::log(90.0));
    const double z = random.uniform();
    const double phi = 2.0 * std::numbers::pi * random.uniform();
    const double radius = std::sqrt(std::max(0.0, 1.0 - z * z));
    const Vector3 centre(radius * std::cos(phi), radius * std::sin(phi), z);
    Vector3 u = perpendicular(centre);
    Vector3 w = centre.cross(u);
    const double turn = 2.0 * std::numbers::pi * random.uniform();
    u = rotated(u, centre, turn);
    w = rotated(w, centre, turn);
    const double tilt = 60.0 * degree * random.uniform();
    const double tilt_axis = 2.0 * std::numbers::pi * random.uniform();
    const Vector3 axis = std::cos(tilt_axis) * u + std::sin(tilt_axis) * w;
    u = rotated(u, axis, tilt);
    w = rotated(w, axis, tilt);
    const double half = std::tan(0.5 * size);
    quads.push_back({{centre + half * (u + w), centre + half * (-u + w), centre + half * (-u - w),
                      centre + half * (u - w)}});
  }
  return quads;
}

QuadIntegral lobe_quad_integral(const brdf::Lobe& lobe, const Quad& quad, const Vector3& peak,
                                const QuadIntegralOptions& options) {
  const std::vector<Vector3> polygon = clipped_to_horizon(quad);
  if (polygon.size() < 3) return {};
  Vector3 normal = (quad.vertices[1] - quad.vertices[0]).cross(quad.vertices[2] - quad.vertices[0]).normalized();
  const Vector3 apex = fan_apex(polygon, normal, peak.normalized());
  std::vector<FanTriangle> triangles;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vector3& from = polygon[i];
    const Vector3 edge = polygon[(i + 1) % polygon.size()] - from;
    const double double_area = (from - apex).cross(edge).norm();
    if (double_area > 1e-14 * edge.squaredNorm()) triangles.push_back({apex, from, edge, double_area});
  }
  if (triangles.empty()) return {};
  const FanIntegrand integrand(lobe, triangles, normal);
  std::vector<integrate::Box<2>> tiles;
  const std::size_t split = std::max<std::size_t>(1, options.initial_tiles_per_side);
  const double step = 1.0 / double(split);
  for (std::size_t k = 0; k < triangles.size(); ++k)
    for (std::size_t i = 0; i < split; ++i)
      for (std::size_t j = 0; j < split; ++j) {
        // The last tile ends exactly on the triangle's edge, so no tile straddles two triangles.
        const double s1 = i + 1 == split ? double(k + 1) : double(k) + double(i + 1) * step;
        const double t1 = j + 1 == split ? 1.0 : double(j + 1) * step;
        tiles.push_back({{double(k) + double(i) * step, double(j) * step}, {s1, t1}});
      }
  integrate::AdaptiveOptions adaptive;
  adaptive.abs_tolerance = options.absolute_tolerance;
  adaptive.rel_tolerance = options.relative_tolerance;
  adaptive.max_evaluations = options.max_evaluations;
  const auto result = integrate::integrate_adaptive<2, 1>(integrand, std::span<const integrate::Box<2>>(tiles), adaptive);
  double solid_angle = 0.0;
  for (const FanTriangle& t : triangles) solid_angle += triangle_solid_angle(t.apex, t.from, t.from + t.edge);
  return {result.value[0], result.error_estimate, solid_angle, result.evaluations, result.converged};
}

double ltc_quad_integral(const LtcDistribution& ltc, const Quad& quad) {
  return ltc.integrate_polygon(std::span<const Vector3>(quad.vertices));
}

double lobe_peak_value(const brdf::Lobe& lobe, const Vector3& peak) {
  // The peak and a grid of the upper hemisphere, valued in one call (Lobe::value_many: vector code where
  // the lobe has it, the same values as one direction at a time).
  constexpr int rings = 32, sectors = 64;
  std::vector<Vector3> directions{peak.normalized()};
  directions.reserve(1 + rings * sectors);
  for (int i = 0; i < rings; ++i) {
    const double z = 1.0 - (i + 0.5) / rings;
    const double radius = std::sqrt(std::max(0.0, 1.0 - z * z));
    for (int j = 0; j < sectors; ++j) {
      const double phi = 2.0 * std::numbers::pi * (j + 0.5) / sectors;
      directions.emplace_back(radius * std::cos(phi), radius * std::sin(phi), z);
    }
  }
  std::vector<double> values(directions.size());
  lobe.value_many(directions, values);
  double best = values.front();
  for (const double value : values) best = std::max(best, value);
  return best;
}

PolygonErrors polygon_errors(std::span<const QuadIntegral> reference, std::span<const double> approximation,
                             double peak_value, double share) {
  if (reference.size() != approximation.size()) throw std::invalid_argument("ltc: polygon errors need matching sizes");
  std::vector<double> errors;
  double absolute = 0.0, total = 0.0;
  for (std::size_t i = 0; i < reference.size(); ++i) {
    const QuadIntegral& r = reference[i];
    absolute += std::abs(approximation[i] - r.value);
    total += r.value;
    if (r.value > 0.0 && r.solid_angle > 0.0 && r.value >= share * peak_value * r.solid_angle)
      errors.push_back(std::abs(approximation[i] - r.value) / r.value);
  }
  PolygonErrors out;
  out.counted = errors.size();
  out.weighted = total > 0.0 ? absolute / total : std::numeric_limits<double>::quiet_NaN();
  if (errors.empty()) {
    out.median = out.p95 = std::numeric_limits<double>::quiet_NaN();
    return out;
  }
  std::sort(errors.begin(), errors.end());
  const auto quantile = [&](double q) {
    const double position = q * double(errors.size() - 1);
    const std::size_t below = static_cast<std::size_t>(position);
    const std::size_t above = std::min(below + 1, errors.size() - 1);
    return errors[below] + (position - double(below)) * (errors[above] - errors[below]);
  };
  out.median = quantile(0.5);
  out.p95 = quantile(0.95);
  return out;
}

PolygonLights::PolygonLights(const brdf::Lobe& lobe, std::vector<Quad> quads, const Vector3& peak,
                             const QuadIntegralOptions& options)
    : quads_(std::move(quads)), peak_value_(lobe_peak_value(lobe, peak)) {
  reference_.reserve(quads_.size());
  for (const Quad& quad : quads_) reference_.push_back(lobe_quad_integral(lobe, quad, peak, options));
}

std::vector<double> PolygonLights::integrals(const LtcDistribution& ltc) const {
  std::vector<double> out;
  out.reserve(quads_.size());
  for (const Quad& quad : quads_) out.push_back(ltc_quad_integral(ltc, quad));
  return out;
}

PolygonErrors PolygonLights::errors(const LtcDistribution& ltc) const {
  return polygon_errors(reference_, integrals(ltc), peak_value_);
}

double PolygonLights::score(const LtcDistribution& ltc) const {
  double squares = 0.0, absolute = 0.0, total = 0.0;
  std::size_t inside = 0;
  for (std::size_t i = 0; i < quads_.size(); ++i) {
    const QuadIntegral& r = reference_[i];
    const double value = ltc_quad_integral(ltc, quads_[i]);
    absolute += std::abs(value - r.value);
    total += r.value;
    if (r.value > 0.0 && r.solid_angle > 0.0 && r.value >= in_lobe_share * peak_value_ * r.solid_angle) {
      const double relative = (value - r.value) / r.value;
      squares += relative * relative;
      ++inside;
    }
  }
  return (inside > 0 ? std::sqrt(squares / double(inside)) : 0.0) + (total > 0.0 ? absolute / total : 0.0);
}

}  // namespace pbrfit::ltc
