#include <catch2/catch_test_macros.hpp>

#include <array>
#include <cmath>
#include <cstring>
#include <vector>
#include <numbers>

#include "kernel_set_scope.hpp"
#include "ltc_sphere_integration.hpp"
#include "pbrfit/core/kernel_set.hpp"
#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/ltc/alignment.hpp"
#include "pbrfit/ltc/clamped_cosine.hpp"
#include "pbrfit/ltc/distribution.hpp"

using namespace pbrfit::ltc;
using pbrfit::Vector3;
using pbrfit::Matrix3;
using pbrfit::RandomStream;
using pbrfit::test::integrate_over_sphere;

namespace {

Matrix3 skewed_anisotropic() {
  Matrix3 m;
  m << 0.45, 0.12, 0.30,  //
      -0.05, 0.80, -0.20,  //
      0.10, 0.02, 1.00;
  return m;
}

Matrix3 isotropic_tilted() {
  Matrix3 m;
  m << 0.60, 0.0, -0.35,  //
      0.0, 0.60, 0.0,     //
      0.0, 0.0, 1.00;
  return m;
}

// The integral of D g over the sphere for a few smooth test functions g, by cubature.
std::array<double, 3> cubature_moments(const LtcDistribution& ltc) {
  const auto f = [&](const Vector3& w) {
    const double d = ltc.evaluate(w);
    return std::array<double, 3>{d * (1.0 + w.x()) * (1.0 + w.x()), d * std::exp(w.z()), d * w.y() * w.z()};
  };
  return integrate_over_sphere<3>(f, 1e-7).value;
}

}  // namespace

TEST_CASE("An LTC integrates to its amplitude over the sphere, isotropic or not", "[ltc]") {
  for (const Matrix3& m : {Matrix3(Matrix3::Identity()), isotropic_tilted(), skewed_anisotropic()}) {
    const LtcDistribution ltc(m, 0.7);
    const auto integral = integrate_over_sphere<1>([&](const Vector3& w) { return std::array{ltc.evaluate(w)}; },
                                                   1e-8);
    CAPTURE(m);
    CHECK(integral.converged);
    CHECK(std::abs(integral.value[0] - 0.7) < 1e-6);
  }
}

TEST_CASE("LTC sampling follows the LTC: sample moments match cubature moments", "[ltc]") {
  for (const Matrix3& m : {isotropic_tilted(), skewed_anisotropic()}) {
    const LtcDistribution ltc(m, 1.3);
    const std::array<double, 3> expected = cubature_moments(ltc);
    RandomStream random(7, 0);
    constexpr int count = 200'000;
    std::array<double, 3> sum{};
    std::array<double, 3> sum_squares{};
    for (int i = 0; i < count; ++i) {
      const double u1 = random.uniform();
      const Vector3 w = ltc.sample(u1, random.uniform());
      const std::array<double, 3> g{(1.0 + w.x()) * (1.0 + w.x()), std::exp(w.z()), w.y() * w.z()};
      for (int k = 0; k < 3; ++k) {
        sum[k] += ltc.amplitude() * g[k];
        sum_squares[k] += ltc.amplitude() * ltc.amplitude() * g[k] * g[k];
      }
    }
    for (int k = 0; k < 3; ++k) {
      const double mean = sum[k] / count;
      const double standard_error = std::sqrt((sum_squares[k] / count - mean * mean) / count);
      CAPTURE(k, mean, expected[k], standard_error);
      CHECK(std::abs(mean - expected[k]) < 4.0 * standard_error);
    }
  }
}

TEST_CASE("transform() gives the sampled direction and the density pdf() gives there", "[ltc]") {
  const LtcDistribution ltc(skewed_anisotropic(), 0.9);
  for (const auto& [u1, u2] : {std::array{0.1, 0.2}, std::array{0.5, 0.9}, std::array{0.93, 0.41}}) {
    const Vector3 base = sample_clamped_cosine(u1, u2);
    const LtcDistribution::Transformed t = ltc.transform(base);
    CHECK((t.direction - ltc.sample(u1, u2)).norm() < 1e-14);
    CHECK(std::abs(t.pdf - ltc.pdf(t.direction)) < 1e-12 * t.pdf);
    CHECK(std::abs(ltc.evaluate(t.direction) - 0.9 * t.pdf) < 1e-12 * t.pdf);
  }
}

TEST_CASE("An LTC is unchanged by scale, rotation about z and the y flip of its matrix", "[ltc]") {
  const Matrix3 m = skewed_anisotropic();
  const Matrix3 flip = Vector3(1.0, -1.0, 1.0).asDiagonal();
  const LtcDistribution reference(m);
  const LtcDistribution equivalent(2.5 * m * rotation_about_z(0.8) * flip);
  RandomStream random(3, 0);
  for (int i = 0; i < 20; ++i) {
    const double u = 2.0 * random.uniform() - 1.0;
    const Vector3 w = pbrfit::test::sphere_direction(u, 2.0 * std::numbers::pi * random.uniform());
    CHECK(std::abs(reference.evaluate(w) - equivalent.evaluate(w)) <= 1e-12 * (1.0 + reference.evaluate(w)));
  }
}

TEST_CASE("A singular matrix or a negative amplitude is rejected", "[ltc]") {
  Matrix3 singular = Matrix3::Identity();
  singular(2, 2) = 0.0;
  CHECK_THROWS_AS(LtcDistribution(singular), std::invalid_argument);
  CHECK_THROWS_AS(LtcDistribution(Matrix3::Identity(), -1.0), std::invalid_argument);
}

// The batch members run as vector code (ltc/ltc_batch.hpp) with the scalar members' arithmetic and sqrt in
// their order: LTC fits, which estimate their error through them, keep their bits in every kernel set.
TEST_CASE("LTC transform_many and pdf_many are transform and pdf bit for bit in every kernel set", "[ltc]") {
  RandomStream random(2026, 12, 7);
  for (int trial = 0; trial < 20; ++trial) {
    Matrix3 m;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m(r, c) = (r == c ? 1.0 : 0.0) + (trial == 0 ? 0.0 : 2.0 * random.uniform() - 1.0);
    const LtcDistribution ltc(m, 0.7);
    std::vector<Vector3> base, sphere;
    for (int i = 0; i < 203; ++i) {  // not a multiple of the 16 lanes
      base.push_back(sample_clamped_cosine(random.uniform(), random.uniform()));
      const double z = 2.0 * random.uniform() - 1.0, phi = 2.0 * std::numbers::pi * random.uniform();
      const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
      sphere.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
    }
    sphere.emplace_back(1.0, 0.0, 0.0);
    for (const pbrfit::KernelSet set : pbrfit::kernel_sets_available()) {
      const kernel_test::KernelSetScope scope(set);
      std::vector<Vector3> directions(base.size());
      std::vector<double> transformed_pdf(base.size()), pdf(sphere.size());
      ltc.transform_many(base, directions, transformed_pdf);
      ltc.pdf_many(sphere, pdf);
      std::size_t differing = 0;
      for (std::size_t i = 0; i < base.size(); ++i) {
        const LtcDistribution::Transformed scalar = ltc.transform(base[i]);
        if (std::memcmp(scalar.direction.data(), directions[i].data(), 3 * sizeof(double)) != 0 ||
            std::memcmp(&scalar.pdf, &transformed_pdf[i], sizeof(double)) != 0)
          ++differing;
      }
      for (std::size_t i = 0; i < sphere.size(); ++i) {
        const double scalar = ltc.pdf(sphere[i]);
        if (std::memcmp(&scalar, &pdf[i], sizeof(double)) != 0) ++differing;
      }
      CAPTURE(pbrfit::kernel_set_name(set), trial);
      CHECK(differing == 0);
    }
  }
}
