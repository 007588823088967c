#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <cstring>
#include <vector>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/ltc/alignment.hpp"
#include "pbrfit/ltc/anisotropic_fit.hpp"
#include "pbrfit/ltc/clamped_cosine.hpp"
#include "pbrfit/ltc/moment_matching.hpp"
#include "pbrfit/ltc/sgd_fit.hpp"
#include "pbrfit/ltc/sliced_wasserstein.hpp"

using namespace pbrfit::ltc;
using pbrfit::Vector3;
using pbrfit::Matrix3;
using pbrfit::RandomStream;

namespace {

Matrix3 skewed_lobe() {
  Matrix3 m;
  m << 0.35, 0.08, 0.25,  //
      -0.05, 0.60, 0.0,   //
      0.05, 0.0, 1.0;
  return m;
}

// Directions drawn from the LTC of m with random cosine samples (independent of the fitter's lattice).
std::vector<Vector3> ltc_samples(const Matrix3& m, int count, std::uint64_t seed) {
  RandomStream random(seed, 0);
  std::vector<Vector3> samples;
  for (int i = 0; i < count; ++i) {
    const double u1 = random.uniform();
    samples.push_back((m * sample_clamped_cosine(u1, random.uniform())).normalized());
  }
  return samples;
}

Matrix3 unit_norm(const Matrix3& m) { return m / m.norm(); }

}  // namespace

TEST_CASE("Sliced Wasserstein fitting recovers a known anisotropic LTC from its own samples", "[ltc]") {
  const Matrix3 truth = skewed_lobe();
  const std::vector<Vector3> targets = ltc_samples(truth, 256, 5);
  const AnisotropicFit fit = fit_ltc_to_samples(targets, 0.8, AnisotropicFitOptions{});
  SlicedWasserstein loss(targets);
  CAPTURE(fit.distance, fit.start_distance, loss.distance(truth), fit.evaluations);
  CHECK(fit.amplitude == 0.8);
  CHECK(fit.distance <= loss.distance(truth));  // at least as close to the samples as the truth
  CHECK(fit.distance < 0.5 * fit.start_distance);
  CHECK(fit.evaluations <= AnisotropicFitOptions{}.max_evaluations);
  const Matrix3 aligned = align_to_matrix(fit.matrix, truth);
  CAPTURE(unit_norm(aligned), unit_norm(truth));
  CHECK((unit_norm(aligned) - unit_norm(truth)).norm() < 0.1);  // 256 samples: a few % per entry
}

TEST_CASE("The anisotropic fit is bitwise reproducible", "[ltc]") {
  const std::vector<Vector3> targets = ltc_samples(skewed_lobe(), 128, 6);
  AnisotropicFitOptions options;
  options.max_evaluations = 300;
  const AnisotropicFit first = fit_ltc_to_samples(targets, 1.0, options);
  const AnisotropicFit second = fit_ltc_to_samples(targets, 1.0, options);
  CHECK(std::memcmp(first.matrix.data(), second.matrix.data(), 9 * sizeof(double)) == 0);
  CHECK(std::memcmp(&first.distance, &second.distance, sizeof(double)) == 0);
}

TEST_CASE("Moment matching recovers a rotated isotropic lobe", "[ltc]") {
  Matrix3 lobe = Vector3(0.3, 0.3, 1.0).asDiagonal();
  const Matrix3 rotation = Eigen::AngleAxisd(0.5, Vector3(0.2, 1.0, 0.0).normalized()).toRotationMatrix();
  const Matrix3 truth = rotation * lobe;
  const Matrix3 start = moment_matched_ltc(ltc_samples(truth, 20000, 7));
  CAPTURE(unit_norm(align_to_matrix(start, truth)), unit_norm(truth));
  CHECK((unit_norm(align_to_matrix(start, truth)) - unit_norm(truth)).norm() < 0.02);
}

TEST_CASE("The isotropic second moment is 1/4 for the cosine, increasing, and matches sampling", "[ltc]") {
  CHECK(std::abs(isotropic_second_moment(1.0) - 0.25) < 1e-12);
  CHECK(std::abs(isotropic_second_moment(1.0 + 1e-5) - isotropic_second_moment(1.0 - 1e-5)) < 1e-4);
  double previous = 0.0;
  for (double m = 0.01; m < 50.0; m *= 1.5) {
    CHECK(isotropic_second_moment(m) > previous);
    previous = isotropic_second_moment(m);
  }
  CHECK(previous < 0.5);
  const auto samples = ltc_samples(Vector3(0.3, 0.3, 1.0).asDiagonal(), 200000, 8);
  double sum = 0.0;
  for (const Vector3& w : samples) sum += w.x() * w.x();
  CHECK(std::abs(sum / 200000.0 - isotropic_second_moment(0.3)) < 5e-4);
}

TEST_CASE("The sliced Wasserstein gradient matches finite differences", "[ltc]") {
  const std::vector<Vector3> targets = ltc_samples(skewed_lobe(), 64, 9);
  SlicedWasserstein loss(targets, 8);
  Matrix3 m = Matrix3::Identity();
  m(0, 2) = 0.2;
  Matrix3 gradient;
  loss.gradient(m, gradient);
  constexpr double h = 1e-7;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      Matrix3 plus = m;
      Matrix3 minus = m;
      plus(r, c) += h;
      minus(r, c) -= h;
      const double numeric = (loss.distance(plus) - loss.distance(minus)) / (2.0 * h);
      CAPTURE(r, c, numeric, gradient(r, c));
      CHECK(std::abs(numeric - gradient(r, c)) < 1e-5);
    }
  }
  CHECK(std::abs(loss.distance(m) - loss.distance(3.0 * m)) < 1e-12);  // scale invariance
}

TEST_CASE("The SGD baseline from the identity improves on the cosine, reproducibly", "[ltc]") {
  const std::vector<Vector3> targets = ltc_samples(skewed_lobe(), 128, 10);
  SlicedWasserstein loss(targets);
  RandomStream first_stream(11, 0);
  RandomStream second_stream(11, 0);
  const Matrix3 first = sgd_fit_from_identity(targets, SgdOptions{}, first_stream);
  const Matrix3 second = sgd_fit_from_identity(targets, SgdOptions{}, second_stream);
  CHECK(std::memcmp(first.data(), second.data(), 9 * sizeof(double)) == 0);
  CAPTURE(loss.distance(first), loss.distance(Matrix3::Identity()));
  CHECK(loss.distance(first) < 0.3 * loss.distance(Matrix3::Identity()));
}

TEST_CASE("Alignment picks the representative closest to the reference", "[ltc]") {
  const Matrix3 m = skewed_lobe();
  const Matrix3 flip = Vector3(1.0, -1.0, 1.0).asDiagonal();
  for (const double phi : {0.3, 1.7, -2.9}) {
    for (const bool flipped : {false, true}) {
      const Matrix3 equivalent = 1.7 * m * rotation_about_z(phi) * (flipped ? flip : Matrix3(Matrix3::Identity()));
      const Matrix3 aligned = align_to_matrix(equivalent, m);
      CAPTURE(phi, flipped, aligned);
      CHECK((aligned / 1.7 - m).norm() < 1e-9);  // back to the reference, scale kept
      const Matrix3 by_samples = align_to_samples(equivalent, m, cosine_samples(256));
      CHECK((by_samples / 1.7 - m).norm() < 1e-6);
    }
  }
}

TEST_CASE("Aligning to the cosine's samples gives one representative per LTC", "[ltc]") {
  const Matrix3 m = skewed_lobe();
  const std::vector<Vector3> base = cosine_samples(512);
  const Matrix3 canonical = align_to_samples(m, Matrix3::Identity(), base);
  const Matrix3 other = align_to_samples(m * rotation_about_z(2.2) * Vector3(1.0, -1.0, 1.0).asDiagonal(),
                                         Matrix3::Identity(), base);
  CAPTURE(canonical, other);
  CHECK((canonical - other).norm() < 1e-6);
  // Never farther from the reference's samples than the input was.
  const auto distance = [&](const Matrix3& candidate) {
    double sum = 0.0;
    for (const Vector3& s : base) sum += ((candidate * s).normalized() - s).squaredNorm();
    return sum;
  };
  CHECK(distance(canonical) <= distance(m) + 1e-12);
}
