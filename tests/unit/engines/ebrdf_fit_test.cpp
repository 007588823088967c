#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <vector>

#include "pbrfit/ebrdf/ebrdf_fit.hpp"
#include "pbrfit/ltc/alignment.hpp"
#include "pbrfit/ltc/clamped_cosine.hpp"
#include "pbrfit/ltc/descent_fit.hpp"

using namespace pbrfit::ebrdf;
using pbrfit::RandomStream;
using pbrfit::Matrix3;
using pbrfit::Vector3;

namespace {

std::vector<Vector3> ltc_samples(const Matrix3& m, int count, std::uint64_t seed) {
  RandomStream random(seed, 0);
  std::vector<Vector3> samples;
  for (int i = 0; i < count; ++i) {
    const double u1 = random.uniform();
    samples.push_back((m * pbrfit::ltc::sample_clamped_cosine(u1, random.uniform())).normalized());
  }
  return samples;
}

Matrix3 skewed() {
  Matrix3 m;
  m << 0.3, 0.05, 0.4,  //
      0.02, 0.15, -0.1, //
      -0.1, 0.0, 1.0;
  return m;
}

}  // namespace

TEST_CASE("gradient descent recovers an LTC from its samples and never ends above its start") {
  const auto samples = ltc_samples(skewed(), 512, 3);
  const auto fit = pbrfit::ltc::fit_ltc_by_descent(samples, 0.7, nullptr, {16, 200, 0.5});
  CHECK(fit.distance <= fit.start_distance);
  CHECK(fit.distance < 0.01);
  CHECK(fit.evaluations == 202);
  CHECK(std::abs(fit.matrix.norm() - 1.0) < 1e-12);
  const Matrix3 truth = skewed() / skewed().norm();
  CHECK((pbrfit::ltc::align_to_matrix(fit.matrix, truth) / fit.matrix.norm() - truth).norm() < 0.1);
  // A warm start at the truth is taken over the moment-matched one.
  const auto warm = pbrfit::ltc::fit_ltc_by_descent(samples, 0.7, &truth, {16, 0, 0.5});
  CHECK(warm.start_distance < fit.start_distance + 1e-12);
}

TEST_CASE("eBRDF fits are aligned, of unit determinant, and descent beats the SGD baseline") {
  const auto samples = ltc_samples(skewed(), 128, 4);
  RandomStream random(1, 2);
  EbrdfFitSettings settings;
  const EbrdfFit descent = fit_ebrdf(samples, 0.8, settings, random);
  settings.method = FitMethod::sgd;
  const EbrdfFit sgd = fit_ebrdf(samples, 0.8, settings, random);
  settings.method = FitMethod::nelder_mead;
  settings.search.max_evaluations = 300;
  const EbrdfFit simplex = fit_ebrdf(samples, 0.8, settings, random);
  for (const EbrdfFit* fit : {&descent, &sgd, &simplex}) {
    const Matrix3 m = fit_matrix(*fit);
    CHECK(std::abs(std::abs(m.determinant()) - 1.0) < 1e-9);
    CHECK(fit->amplitude == 0.8);
    CHECK(fit->error > 0.0);
    // Aligned: no other representative M F^k R(phi) is closer to the cosine's samples.
    const Matrix3 realigned = pbrfit::ltc::align_to_samples(m, Matrix3::Identity(), pbrfit::ltc::cosine_samples(32));
    CHECK((realigned - m).norm() < 1e-3);
  }
  CHECK(descent.error < sgd.error);
  CHECK(sgd.evaluations == 100);
}
