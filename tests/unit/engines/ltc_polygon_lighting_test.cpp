#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <cstring>
#include <numbers>
#include <random>
#include <vector>

#include "fan_points.hpp"
#include "pbrfit/brdf/brdf_families.hpp"
#include "pbrfit/brdf/ggx_lobe.hpp"
#include "pbrfit/core/kernel_set.hpp"
#include "pbrfit/ltc/distribution.hpp"
#include "pbrfit/ltc/polygon_integral.hpp"
#include "pbrfit/ltc/polygon_lighting.hpp"

using namespace pbrfit::ltc;
using pbrfit::KernelSet;
using pbrfit::Matrix3;
using pbrfit::Vector3;

namespace {

double angle_between(const Vector3& a, const Vector3& b) { return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)); }

}  // namespace

TEST_CASE("The quad lights are a fixed set of sizes from 1 to 90 degrees, some crossing the horizon", "[ltc]") {
  const auto quads = random_quads(200);
  REQUIRE(quads.size() == 200);
  CHECK(random_quads(200, polygon_quad_seed)[17].vertices == quads[17].vertices);
  int crossing = 0;
  for (const Quad& q : quads) {
    const Vector3 centre = 0.25 * (q.vertices[0] + q.vertices[1] + q.vertices[2] + q.vertices[3]);
    CHECK(centre.z() >= -1e-12);
    const double side = angle_between(q.vertices[0], q.vertices[1]);
    CHECK(side > 0.5 * std::numbers::pi / 180.0);
    CHECK(side < 2.0 * std::numbers::pi / 2.0);
    const Vector3 normal = (q.vertices[1] - q.vertices[0]).cross(q.vertices[2] - q.vertices[0]).normalized();
    CHECK(std::abs(normal.dot(q.vertices[0])) > 0.4);  // the plane stays away from the shading point
    bool below = false, above = false;
    for (const Vector3& p : q.vertices) (p.z() < 0.0 ? below : above) = true;
    crossing += below && above;
  }
  CHECK(crossing > 5);
  CHECK(crossing < 100);
}

TEST_CASE("The lobe's quad integral of a cosine lobe is Lambert's formula", "[ltc]") {
  const auto lambert = pbrfit::brdf::make_family_lobe(pbrfit::brdf::BrdfFamily::fabric_lambert, 0.0, 0.6);
  for (const Quad& q : random_quads(40)) {
    const QuadIntegral integral = lobe_quad_integral(*lambert, q, Vector3::UnitZ());
    const double exact = clamped_cosine_polygon_integral(std::span<const Vector3>(q.vertices));
    CAPTURE(integral.value, exact, integral.evaluations);
    CHECK(integral.converged);
    CHECK(std::abs(integral.value - exact) <= 2e-4 * exact + 1e-10);
    // The identity LTC with amplitude 1 is that cosine lobe, seen by the shader's own formula.
    const LtcDistribution identity(Matrix3::Identity(), 1.0);
    CHECK(std::abs(ltc_quad_integral(identity, q) - exact) < 1e-12);
  }
}

TEST_CASE("A sharp lobe's quad integrals add up over a split quad", "[ltc]") {
  // A quad around the mirror direction of a sharp GGX lobe, split into four: the parts sum to the whole, each
  // found with its own fan and apex.
  const pbrfit::brdf::GgxLobe lobe(0.01, 0.7);
  const Vector3 mirror = pbrfit::brdf::mirror_about_normal(lobe.view());
  const pbrfit::Frame frame = pbrfit::Frame::from_z(mirror);
  const auto at = [&](double a, double b) { return Vector3(mirror + 0.2 * (a * frame.x + b * frame.y)); };
  const Quad whole{{at(-1.1, -0.9), at(0.9, -1.1), at(1.0, 1.0), at(-1.0, 0.8)}};
  const Vector3 middle = at(0.03, -0.02);
  const auto half = [](const Vector3& a, const Vector3& b) { return Vector3(0.5 * (a + b)); };
  const auto& v = whole.vertices;
  const std::vector<Quad> parts = {{{v[0], half(v[0], v[1]), middle, half(v[3], v[0])}},
                                   {{half(v[0], v[1]), v[1], half(v[1], v[2]), middle}},
                                   {{middle, half(v[1], v[2]), v[2], half(v[2], v[3])}},
                                   {{half(v[3], v[0]), middle, half(v[2], v[3]), v[3]}}};
  QuadIntegralOptions tight;
  tight.relative_tolerance = 1e-6;
  const double total = lobe_quad_integral(lobe, whole, mirror, tight).value;
  double sum = 0.0;
  for (const Quad& part : parts) sum += lobe_quad_integral(lobe, part, mirror, tight).value;
  CAPTURE(total, sum);
  CHECK(total > 0.5);  // most of the lobe
  CHECK(std::abs(sum - total) < 1e-5 * total);
}

TEST_CASE("Polygon errors are quantiles of the relative errors over the lights inside the lobe", "[ltc]") {
  // Lights of solid angle 1; the lobe's peak value is 10, so a light counts when its integral is >= 0.1.
  const auto light = [](double value) { return QuadIntegral{value, 0.0, 1.0, 0, true}; };
  const std::vector<QuadIntegral> reference = {light(1.0), light(2.0), light(4.0), light(0.05), light(8.0), light(0.5)};
  const std::vector<double> approximation = {1.1, 1.8, 4.0, 1.0, 8.8, 0.5};
  const PolygonErrors e = polygon_errors(reference, approximation, 10.0);
  CHECK(e.counted == 5);  // the light in the lobe's far tail says nothing relative
  CHECK(std::abs(e.median - 0.1) < 1e-12);  // sorted: 0, 0, 0.1, 0.1, 0.1
  CHECK(std::abs(e.p95 - 0.1) < 1e-12);
  CHECK(std::abs(e.weighted - (0.1 + 0.2 + 0.0 + 0.95 + 0.8 + 0.0) / 15.55) < 1e-12);  // every light
  const PolygonErrors none = polygon_errors(std::vector<QuadIntegral>{light(0.0)}, std::vector<double>{1.0}, 10.0);
  CHECK(none.counted == 0);
  CHECK(std::isnan(none.median));
}

TEST_CASE("A quad's solid angle is that of its part above the horizon", "[ltc]") {
  // A square of half-side 1 at distance 1 straight above subtends 4 asin(1/3) = 2 pi / 3.
  const Quad square{{Vector3(1, 1, 1), Vector3(-1, 1, 1), Vector3(-1, -1, 1), Vector3(1, -1, 1)}};
  const auto lambert = pbrfit::brdf::make_family_lobe(pbrfit::brdf::BrdfFamily::fabric_lambert, 0.0, 1.0);
  CHECK(std::abs(lobe_quad_integral(*lambert, square, Vector3::UnitZ()).solid_angle - 2.0 * std::numbers::pi / 3.0) < 1e-12);
  // A wall at x = 1 reaching from z = -1 to 1: half of it is above the horizon.
  const Quad wall{{Vector3(1, 1, 1), Vector3(1, -1, 1), Vector3(1, -1, -1), Vector3(1, 1, -1)}};
  CHECK(std::abs(lobe_quad_integral(*lambert, wall, Vector3::UnitZ()).solid_angle - std::numbers::pi / 3.0) < 1e-12);
}

TEST_CASE("The fan integrand's points are the scalar formula's, bit for bit, in every kernel set", "[ltc][kernels]") {
  // The points of polygon_lighting.cpp's fan integrand one at a time with Eigen, as before they ran as vector
  // code: x = apex + t ((from + s edge) - apex), t = tau^4.
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const auto vector = [&] { return Vector3(uniform(random), uniform(random), 0.5 + uniform(random)); };
  for (int trial = 0; trial < 50; ++trial) {
    const Vector3 apex = vector(), from = vector(), edge = vector() - from;
    const Vector3 normal = vector().normalized();
    const double double_area = 0.1 + std::abs(uniform(random)), s = 0.5 * (1.0 + uniform(random));
    std::vector<double> tau(pbrfit::ltc::detail::fan_line_points);
    for (double& u : tau) u = 0.5 * (1.0 + uniform(random));
    const std::size_t n = 1 + std::size_t(trial) % tau.size();
    std::vector<Vector3> expected_directions(n);
    std::vector<double> expected_solid(n), expected_jacobian(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double tau2 = tau[i] * tau[i], t4 = tau2 * tau2;
      const Vector3 point = apex + t4 * (from + s * edge - apex);
      const double length2 = point.squaredNorm();
      const double length = std::sqrt(length2);
      expected_directions[i] = point / length;
      expected_solid[i] = std::abs(normal.dot(point)) / (length2 * length);
      expected_jacobian[i] = double_area * t4 * 4.0 * tau2 * tau[i];
    }
    for (const KernelSet set : pbrfit::kernel_sets_available()) {
      std::vector<Vector3> directions(n);
      std::vector<double> solid(n), jacobian(n);
      pbrfit::ltc::detail::fan_points(set)({apex, from, edge, normal, double_area, s}, tau.data(), n,
                                           directions.data(), solid.data(), jacobian.data());
      CAPTURE(pbrfit::kernel_set_name(set), trial, n);
      CHECK(std::memcmp(directions.data(), expected_directions.data(), n * sizeof(Vector3)) == 0);
      CHECK(std::memcmp(solid.data(), expected_solid.data(), n * sizeof(double)) == 0);
      CHECK(std::memcmp(jacobian.data(), expected_jacobian.data(), n * sizeof(double)) == 0);
    }
  }
}
