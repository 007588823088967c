#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <vector>

#include "ltc_reference_table.hpp"
#include "pbrfit/ltc/ggx_table.hpp"
#include "pbrfit/ltc/isotropic_parameters.hpp"
#include "pbrfit/ltc/shader_form.hpp"
#include "pbrfit/ltc/sphere_form_factor.hpp"

using namespace pbrfit::ltc;
using pbrfit::Vector3;
using pbrfit::Matrix3;

TEST_CASE("The 4-number shader form round-trips to the matrix up to scale", "[ltc]") {
  const Vector3 lobe = Vector3(-0.4, 0.0, 0.9).normalized();
  for (const IsotropicParameters& p : {IsotropicParameters{0.3, 0.2, -0.1}, IsotropicParameters{1.1, 0.9, 0.4},
                                       IsotropicParameters{2e-5, 2e-5, 0.0}}) {
    const Matrix3 m = isotropic_ltc_matrix(p, lobe);
    const ShaderForm form = shader_form(m);
    const Matrix3 inverse = m.inverse();
    CHECK(std::abs(form[0] - inverse(0, 0) / inverse(1, 1)) < 1e-15);
    CHECK(std::abs(form[1] - inverse(2, 0) / inverse(1, 1)) < 1e-15);
    CHECK(std::abs(form[2] - inverse(0, 2) / inverse(1, 1)) < 1e-15);
    CHECK(std::abs(form[3] - inverse(2, 2) / inverse(1, 1)) < 1e-15);
    const Matrix3 back = matrix_from_shader_form(form);
    CAPTURE(m, back);
    CHECK((back - m / m(1, 1)).norm() < 1e-10 * (m / m(1, 1)).norm());
    CHECK((inverse_from_shader_form(form) - inverse / inverse(1, 1)).norm() < 1e-12 * (inverse / inverse(1, 1)).norm());
  }
}

TEST_CASE("A matrix whose inverse has a zero middle entry has no shader form", "[ltc]") {
  Matrix3 singular = Matrix3::Identity();
  singular(1, 1) = 0.0;
  CHECK_THROWS_AS(shader_form(singular), std::invalid_argument);
}

TEST_CASE("The published table reads as 4096 cells in the documented layout", "[ltc]") {
  const auto cells = pbrfit::test::read_published_ltc_table(pbrfit::test::published_ltc_table_path());
  REQUIRE(cells.size() == 4096);
  const GgxTableLayout layout;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const TableCell cell{cells[i].roughness_index, cells[i].view_index};
    REQUIRE(layout.flat_index(cell) == i);
  }
  // Normal view: the inverse is diag(1, 1, m) up to scale, with m about twice alpha for smooth GGX.
  const auto& smooth = cells[layout.flat_index({5, 0})];
  CHECK(smooth.ltc1[0] == 1.0);
  CHECK(std::abs(smooth.ltc1[3] / (2.0 * layout.alpha({5, 0})) - 1.0) < 0.01);
  // A forward matrix rebuilt from the shader form maps z to the mirror side of the view.
  const Matrix3 m = matrix_from_shader_form(cells[layout.flat_index({10, 30})].ltc1);
  CHECK((m * Vector3::UnitZ()).x() < 0.0);
}

TEST_CASE("The published sphere column is the cap form factor ratio at its own axes", "[ltc]") {
  const auto cells = pbrfit::test::read_published_ltc_table(pbrfit::test::published_ltc_table_path());
  const GgxTableLayout layout;
  double worst = 0.0;
  for (const auto& published : cells) {
    const TableCell cell{published.roughness_index, published.view_index};
    worst = std::max(worst, std::abs(layout.sphere_term(cell) - published.sphere));
  }
  CHECK(worst < 5e-6);  // the table holds 6 significant digits of single-precision values
}

TEST_CASE("Table layout: axes, clamps and the marching order", "[ltc]") {
  const GgxTableLayout layout;
  CHECK(layout.alpha({0, 0}) == 1e-5);
  CHECK(layout.alpha({63, 0}) == 1.0);
  CHECK(layout.cos_theta_view({0, 0}) == 1.0);
  CHECK(std::abs(layout.cos_theta_view({0, 63}) - std::cos(1.57)) < 1e-15);
  CHECK(std::abs(layout.cos_theta_view({0, 21}) - (1.0 - (21.0 / 63) * (21.0 / 63))) < 1e-15);
  const auto order = marching_order(layout);
  REQUIRE(order.size() == 4096);
  std::vector<bool> seen(4096, false);
  for (const MarchingStep& step : order) {
    if (step.predecessor) CHECK(seen[layout.flat_index(*step.predecessor)]);
    seen[layout.flat_index(step.cell)] = true;
  }
  CHECK(order.front().cell.roughness_index == 63);
  CHECK(!order.front().predecessor);
}
