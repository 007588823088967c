#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "pbrfit/brdf/disney_diffuse.hpp"
#include "pbrfit/brdf/disney_diffuse_course_fit.hpp"
#include "pbrfit/brdf/disney_diffuse_lobe.hpp"
#include "pbrfit/brdf/sh_projection.hpp"
#include "pbrfit/integrate/direction_domain.hpp"

using namespace pbrfit::brdf;
using pbrfit::Vector3;
using pbrfit::Matrix3;
using pbrfit::integrate::AdaptiveOptions;

namespace {

constexpr double pi = std::numbers::pi;
const double y00 = 0.5 / std::sqrt(pi);

AdaptiveOptions tight() {
  AdaptiveOptions options;
  options.abs_tolerance = 1e-8;
  return options;
}

}  // namespace

TEST_CASE("SH projection of the Lambert lobe has the textbook zonal coefficients", "[disney]") {
  const auto lambert = [](const Vector3& l) { return std::max(0.0, l.z()) / pi; };
  const ShProjection projection = project_to_sh(lambert, 0.0, tight());
  REQUIRE(projection.converged);
  const ZonalCoefficients zh = zonal_coefficients(projection.sh, optimal_linear_direction(projection.sh));
  // integral of (cos/pi) Y_l0: Y00, (2/3) sqrt(3/(4 pi)), (1/2) sqrt(5/(16 pi)).
  CHECK(std::abs(zh[0] - y00) < 1e-7);
  CHECK(std::abs(zh[1] - 2.0 / 3.0 * std::sqrt(3.0 / (4.0 * pi))) < 1e-7);
  CHECK(std::abs(zh[2] - 0.5 * std::sqrt(5.0 / (16.0 * pi))) < 1e-7);
  CHECK(optimal_linear_direction(projection.sh).z() > 1.0 - 1e-12);
}

TEST_CASE("Disney diffuse lobe at normal view matches its closed-form ZH0", "[disney]") {
  // At n.v = 1, (l.h)^2 = (1 + mu)/2, so ZH0 = Y00 * 2 * int mu (1 + (r (1 + mu) - 1/2)(1 - mu)^5) dmu
  //                                        = Y00 (1 + (2r - 1)/42 + r/84).
  for (double roughness : {0.0, 0.3, 1.0}) {
    const DisneyDiffuseLobe lobe = disney_diffuse_lobe(roughness, 1.0, tight());
    CAPTURE(roughness, lobe.zh[0]);
    REQUIRE(lobe.converged);
    CHECK(std::abs(lobe.zh[0] - y00 * (1.0 + (2.0 * roughness - 1.0) / 42.0 + roughness / 84.0)) < 1e-7);
    CHECK(lobe.direction.z() > 1.0 - 1e-9);
    CHECK(lobe.beta == 0.0);
  }
}

TEST_CASE("Disney diffuse at roughness 0 is symmetric about n and scales by the view's retro factor", "[disney]") {
  // F_D90 = 0.5 whatever l: the lobe is (1/pi) retro(n.l) retro(n.v) (n.l), an axial lobe about n.
  const DisneyDiffuseLobe normal = disney_diffuse_lobe(0.0, 1.0, tight());
  for (double mu : {0.7, 0.3, 0.05}) {
    const DisneyDiffuseLobe lobe = disney_diffuse_lobe(0.0, mu, tight());
    const double retro = disney_retro_factor(0.5, mu);
    CAPTURE(mu);
    CHECK(std::abs(lobe.beta) < 1e-6);
    for (int l = 0; l < 3; ++l) CHECK(std::abs(lobe.zh[l] - retro * normal.zh[l]) < 1e-7);
  }
}

TEST_CASE("Disney diffuse lobe is mirror-symmetric and its ZH equal direct integrals about its axis", "[disney]") {
  const double roughness = 1.0, mu = 0.1;
  const DisneyDiffuseLobe lobe = disney_diffuse_lobe(roughness, mu, tight());
  for (int index : {1, 4, 5}) CHECK(std::abs(lobe.sh[index]) < 1e-7);
  CHECK(std::abs(lobe.direction.y()) < 1e-6);
  CHECK(lobe.beta > 0.1);  // rough grazing views lean towards v

  // Independent: integrate rho(l) Y_l0(d . l) about d directly (Legendre polynomials).
  const Vector3 view(std::sqrt(1.0 - mu * mu), 0.0, mu);
  const Vector3 axis = lobe.direction;
  const auto about_axis = [&](const pbrfit::integrate::UnitDirection& d) {
    const Vector3 l(d[0], d[1], d[2]);
    const double rho = disney_diffuse_cbrdf(roughness, view, l);
    const double t = axis.dot(l);
    return std::array<double, 3>{rho * y00, rho * std::sqrt(3.0 / (4.0 * pi)) * t,
                                 rho * std::sqrt(5.0 / (16.0 * pi)) * (3.0 * t * t - 1.0)};
  };
  const auto direct = pbrfit::integrate::integrate_over_directions<3>(about_axis, 0.0, 1.0, 4, tight());
  for (int l = 0; l < 3; ++l) CHECK(std::abs(direct.value[l] - lobe.zh[l]) < 1e-6);

  CHECK((blended_direction(lobe.beta, mu) - lobe.direction).norm() < 1e-8);
}

TEST_CASE("the course's beta and ZH ratio fits are close to the integrated lobe", "[disney]") {
  AdaptiveOptions options;
  options.abs_tolerance = 1e-7;
  double ratio1 = 0.0, ratio2 = 0.0, constant1 = 0.0, constant2 = 0.0, beta = 0.0;
  for (int i = 0; i <= 4; ++i) {
    for (int j = 0; j <= 4; ++j) {
      const double roughness = i / 4.0, mu = 0.02 + 0.98 * j / 4.0;
      const DisneyDiffuseLobe lobe = disney_diffuse_lobe(roughness, mu, options);
      const double r1 = lobe.zh[1] / lobe.zh[0], r2 = lobe.zh[2] / lobe.zh[0];
      ratio1 = std::max(ratio1, std::abs(r1 - course_disney_zh1_ratio(roughness, mu)));
      ratio2 = std::max(ratio2, std::abs(r2 - course_disney_zh2_ratio(roughness, mu)));
      constant1 = std::max(constant1, std::abs(r1 - course_disney_zh1_constant_ratio));
      constant2 = std::max(constant2, std::abs(r2 - course_disney_zh2_constant_ratio));
      beta = std::max(beta, std::abs(lobe.beta - course_disney_beta(roughness, mu)));
    }
  }
  CAPTURE(ratio1, ratio2, constant1, constant2, beta);
  // The ratios vary over ~0.06 (ZH1/ZH0) and ~0.1 (ZH2/ZH0) across the domain; beta over ~0.25.
  CHECK(ratio1 < 0.03);
  CHECK(ratio2 < 0.06);
  CHECK(constant1 < 0.03);
  CHECK(constant2 < 0.06);
  CHECK(beta < 0.08);
}
