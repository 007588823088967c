#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "pbrfit/integrate/adaptive_cubature.hpp"
#include "pbrfit/ltc/distribution.hpp"
#include "pbrfit/ltc/polygon_integral.hpp"
#include "pbrfit/ltc/sphere_form_factor.hpp"

using namespace pbrfit::ltc;
using pbrfit::Matrix3;
using pbrfit::Frame;
using pbrfit::Vector3;
using pbrfit::integrate::AdaptiveOptions;
using pbrfit::integrate::Box;

namespace {

using Polygon = std::vector<Vector3>;

// The integral of D over the solid angle of a planar polygon, by cubature over its surface: a fan of
// triangles, each mapped from the unit square (Duffy), with d omega = |n . x| / |x|^3 dA. The triangles'
// areas are signed, so a fan over a concave polygon cancels where it overlaps itself.
double integrate_over_polygon(const Polygon& polygon, const LtcDistribution& ltc) {
  const Vector3 normal = (polygon[1] - polygon[0]).cross(polygon[2] - polygon[0]).normalized();
  double total = 0.0;
  for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
    const Vector3 p0 = polygon[0];
    const Vector3 e1 = polygon[k] - p0;
    const Vector3 e2 = polygon[k + 1] - polygon[k];
    const double area_scale = e1.cross(e2).dot(normal);
    const auto f = [&](const std::array<double, 2>& st) {
      const Vector3 x = p0 + st[0] * e1 + st[0] * st[1] * e2;
      const double r = x.norm();
      return std::array{ltc.evaluate(x / r) * std::abs(normal.dot(x)) / (r * r * r) * st[0] * area_scale};
    };
    const std::array<Box<2>, 1> square{Box<2>{{0.0, 0.0}, {1.0, 1.0}}};
    total += pbrfit::integrate::integrate_adaptive<2, 1>(f, std::span<const Box<2>>(square),
                                                        AdaptiveOptions{1e-9, 4'000'000})
                 .value[0];
  }
  return std::abs(total);
}

// A regular pentagon of circumradius 1.2 around `centre`, in the plane spanned by u and v.
Polygon pentagon(const Vector3& centre, const Vector3& u, const Vector3& v) {
  Polygon polygon;
  for (int k = 0; k < 5; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / 5.0;
    polygon.push_back(centre + 1.2 * (std::cos(angle) * u + std::sin(angle) * v));
  }
  return polygon;
}

std::vector<Polygon> test_polygons() {
  return {
      {{-1, -1, 2}, {1, -1, 2}, {1, 1, 2}, {-1, 1, 2}},                       // above, facing down
      {{1, -1, -0.5}, {1, 1, -0.5}, {1, 1, 1.5}, {1, -1, 1.5}},               // vertical, crossing
      {{0.5, 0.2, 1}, {-0.7, 0.5, -0.8}, {0.3, -1, 0.4}},                     // tilted triangle, crossing
      pentagon({-0.8, 1.0, 0.2}, Vector3(1, 0.3, 0.2).normalized(), Vector3(-0.1, 0.2, 1).normalized()),
      {{-1, 1.5, -1}, {1, 1.5, -1}, {1, 1.5, 0.3}, {0, 1.5, 0.3}, {0, 1.5, -0.4}, {-1, 1.5, -0.4}},  // concave
      {{0, 0, -1}, {1, 0, -1}, {1, 1, -1}},                                   // below the horizon
  };
}

Matrix3 anisotropic() {
  Matrix3 m;
  m << 0.5, 0.1, 0.25,  //
      0.0, 0.9, -0.3,   //
      0.15, 0.05, 1.0;
  return m;
}

}  // namespace

TEST_CASE("The clipped polygon integral of the clamped cosine matches cubature", "[ltc]") {
  const LtcDistribution cosine(Matrix3::Identity());
  for (const Polygon& polygon : test_polygons()) {
    CAPTURE(polygon.size(), polygon[0].transpose());
    const double exact = clamped_cosine_polygon_integral(polygon);
    CHECK(std::abs(exact - integrate_over_polygon(polygon, cosine)) < 1e-7);
    CHECK(exact >= 0.0);
    CHECK(exact <= 1.0);
  }
}

TEST_CASE("LTC polygon integrals match cubature, anisotropic matrices and the horizon included", "[ltc]") {
  Matrix3 tilted;
  tilted << 0.3, 0.0, -0.6, 0.0, 0.3, 0.0, 0.0, 0.0, 1.0;
  for (const Matrix3& m : {tilted, anisotropic()}) {
    const LtcDistribution ltc(m, 0.8);
    for (const Polygon& polygon : test_polygons()) {
      CAPTURE(m, polygon.size(), polygon[0].transpose());
      CHECK(std::abs(ltc.integrate_polygon(polygon) - integrate_over_polygon(polygon, ltc)) < 2e-7);
    }
  }
}

TEST_CASE("The polygon integral ignores winding and starting vertex", "[ltc]") {
  const LtcDistribution ltc(anisotropic());
  for (Polygon polygon : test_polygons()) {
    const double reference = ltc.integrate_polygon(polygon);
    std::rotate(polygon.begin(), polygon.begin() + 1, polygon.end());
    CHECK(std::abs(ltc.integrate_polygon(polygon) - reference) < 1e-14);
    std::reverse(polygon.begin(), polygon.end());
    CHECK(std::abs(ltc.integrate_polygon(polygon) - reference) < 1e-14);
  }
}

TEST_CASE("The vector form factor's z is the signed unclipped integral, and points at the polygon", "[ltc]") {
  const Polygon above{{-1, -1, 2}, {1, -1, 2}, {1, 1, 2}, {-1, 1, 2}};
  const Vector3 f = vector_form_factor(above);
  CHECK(std::abs(f.z() - clamped_cosine_polygon_integral(above)) < 1e-14);  // wound clockwise seen from 0
  CHECK(std::abs(f.x()) < 1e-14);
  CHECK(std::abs(f.y()) < 1e-14);
}

TEST_CASE("The spherical cap form factor matches cubature, across the horizon", "[ltc]") {
  for (const auto& [omega, sigma] : {std::array{0.3, 0.4}, std::array{1.2, 0.6}, std::array{1.6, 0.5},
                                     std::array{1.9, 0.45}, std::array{0.9, 1.2}, std::array{2.8, 0.2}}) {
    const Vector3 centre(std::sin(omega), 0.0, std::cos(omega));
    const Frame frame = Frame::from_z(centre);
    // Over the cap in its own polar coordinates (cos psi in [cos sigma, 1], azimuth).
    const auto f = [&](const std::array<double, 2>& x) {
      const double radius = std::sqrt(std::max(0.0, 1.0 - x[0] * x[0]));
      const Vector3 w = frame.from_local({radius * std::cos(x[1]), radius * std::sin(x[1]), x[0]});
      return std::array{std::max(0.0, w.z()) / std::numbers::pi};
    };
    const std::array<Box<2>, 1> cap{Box<2>{{std::cos(sigma), 0.0}, {1.0, 2.0 * std::numbers::pi}}};
    const double numeric =
        pbrfit::integrate::integrate_adaptive<2, 1>(f, std::span<const Box<2>>(cap), AdaptiveOptions{1e-10}).value[0];
    const double sin_squared = std::sin(sigma) * std::sin(sigma);
    CAPTURE(omega, sigma, numeric);
    CHECK(std::abs(cap_form_factor(std::cos(omega), sin_squared) - numeric) < 1e-8);
    const Vector3 cap_vector = sin_squared * centre;
    CHECK(std::abs(horizon_clipped_form_factor(cap_vector) - numeric) < 1e-8);
  }
}

TEST_CASE("The sphere ratio is max(z, 0) in the point limit and 1 for the upper hemisphere", "[ltc]") {
  CHECK(sphere_form_factor_ratio(0.4, 0.0) == 0.4);
  CHECK(sphere_form_factor_ratio(-0.4, 0.0) == 0.0);
  CHECK(std::abs(sphere_form_factor_ratio(1.0, 1.0) - 1.0) < 1e-12);
  CHECK(std::abs(sphere_form_factor_ratio(0.3, 1e-9) - 0.3) < 1e-6);
}
