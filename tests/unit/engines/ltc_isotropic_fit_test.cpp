#include <catch2/catch_test_macros.hpp>

#include <cstring>
#include <memory>
#include <utility>
#include <vector>

#include "ltc_reference_table.hpp"
#include "pbrfit/brdf/ggx_lobe.hpp"
#include "pbrfit/ltc/distribution.hpp"
#include "pbrfit/ltc/fit_error.hpp"
#include "pbrfit/ltc/ggx_table.hpp"
#include "pbrfit/ltc/isotropic_fit.hpp"
#include "pbrfit/ltc/isotropic_target.hpp"
#include "pbrfit/ltc/lobe_moments.hpp"
#include "pbrfit/ltc/shader_form.hpp"

using namespace pbrfit::ltc;
using pbrfit::Matrix3;
using pbrfit::Vector3;

namespace {

CellFitOptions small_fit() {
  CellFitOptions options;
  options.objective_points = 256;
  options.moment_points = 2048;
  options.metric_points = 2048;
  return options;
}

// Both errors of the published matrix for a cell, on the same judge lattice and with the same amplitude as
// our fit's reported errors.
FitError published_error(const GgxTableLayout& layout, const TableCell& cell, double amplitude) {
  static const auto published = pbrfit::test::read_published_ltc_table(pbrfit::test::published_ltc_table_path());
  const ShaderForm form = published[layout.flat_index(cell)].ltc1;
  const auto target = std::make_shared<pbrfit::brdf::GgxLobe>(layout.alpha(cell), layout.cos_theta_view(cell));
  return FitErrorEstimator(target, small_fit().metric_points)
      .errors(LtcDistribution(matrix_from_shader_form(form), amplitude));
}

CellFit fit_cell(const GgxTableLayout& layout, const TableCell& cell, const IsotropicParameters& start) {
  return fit_isotropic_cell(std::make_shared<pbrfit::brdf::GgxLobe>(layout.alpha(cell), layout.cos_theta_view(cell)), start, small_fit());
}

void check_not_worse_than_published(const GgxTableLayout& layout, const TableCell& cell, const CellFit& fit) {
  const FitError theirs = published_error(layout, cell, fit.moments.albedo);
  CAPTURE(cell.roughness_index, cell.view_index, fit.error.cubed, theirs.cubed, fit.error.l2, theirs.l2);
  CHECK(fit.error.cubed <= theirs.cubed);
  // L2 is not the objective: where both fits are essentially the same lobe (a = 63, t = 0: m = 1.1278 here,
  // 1.1281 published) ours can be 3e-5 above theirs.
  CHECK(fit.error.l2 <= theirs.l2 * (1.0 + 1e-4));
}

}  // namespace

TEST_CASE("Fits from the identity match or beat the published table at rough and mid cells", "[ltc]") {
  const GgxTableLayout layout;
  const std::vector<TableCell> cells{{63, 0}, {48, 20}, {32, 40}, {20, 10}, {40, 62}, {55, 58}, {25, 30}};
  for (const TableCell& cell : cells) {
    const CellFit fit = fit_cell(layout, cell, IsotropicParameters{});
    check_not_worse_than_published(layout, cell, fit);
  }
}

TEST_CASE("Marching from normal view beats the published table at a smooth cell", "[ltc]") {
  // From the identity a lobe of alpha = 0.006 is out of the search's reach within its budget; the paper's
  // remedy is a warm start from the neighbouring cell, which this march reproduces along one row.
  const GgxTableLayout layout;
  IsotropicParameters start;
  CellFit fit;
  for (int t = 0; t <= 5; ++t) {
    fit = fit_cell(layout, {5, t}, start);
    start = fit.parameters;
  }
  check_not_worse_than_published(layout, {5, 5}, fit);
}

TEST_CASE("A cell fit is bitwise reproducible and keeps the symmetric matrix structure", "[ltc]") {
  const GgxTableLayout layout;
  const TableCell cell{30, 25};
  const CellFit first = fit_cell(layout, cell, IsotropicParameters{});
  const CellFit second = fit_cell(layout, cell, IsotropicParameters{});
  CHECK(std::memcmp(first.matrix.data(), second.matrix.data(), 9 * sizeof(double)) == 0);
  CHECK(std::memcmp(&first.objective, &second.objective, sizeof(double)) == 0);
  CHECK(std::memcmp(&first.error, &second.error, sizeof(FitError)) == 0);
  CHECK(first.evaluations == second.evaluations);
  for (const auto& [row, column] : {std::pair{0, 1}, std::pair{1, 0}, std::pair{1, 2}, std::pair{2, 1}}) {
    CHECK(first.matrix(row, column) == 0.0);
  }
  CHECK(first.evaluations <= small_fit().max_evaluations);
  CHECK((matrix_from_shader_form(first.shader) - first.matrix / first.matrix(1, 1)).norm() < 1e-9);
}

TEST_CASE("At normal view the fit is a rotationally symmetric lobe", "[ltc]") {
  const GgxTableLayout layout;
  const CellFit fit = fit_cell(layout, {40, 0}, IsotropicParameters{});
  CHECK(fit.parameters.m00 == fit.parameters.m11);
  CHECK(fit.parameters.m02 == 0.0);
  CHECK(fit.parameters.m20 == 0.0);
  CHECK(fit.moments.average_direction == Vector3::UnitZ());
}

TEST_CASE("A cell samples its lobe once for moments and judge, with the values of separate samplings", "[ltc]") {
  // IsotropicTarget hands one sample_lobe to both when the lattices agree; the moments and the judge's
  // errors must be those of sampling the lobe for each alone, bit for bit, and so must a judge on its own
  // lattice size (the separate path).
  const auto lobe = std::make_shared<pbrfit::brdf::GgxLobe>(0.35, 0.6);
  Matrix3 m;
  m << 0.6, 0.0, 0.1, 0.0, 0.55, 0.0, -0.2, 0.0, 1.0;
  for (const std::size_t metric_points : {std::size_t{1024}, std::size_t{2048}}) {
    IsotropicTargetOptions options;
    options.objective_points = 256;
    options.moment_points = 1024;
    options.metric_points = metric_points;
    const IsotropicTarget target(lobe, options);
    const LobeMoments moments = measure_moments(*lobe, 1024);
    CHECK(std::memcmp(&target.moments().albedo, &moments.albedo, sizeof(double)) == 0);
    CHECK(std::memcmp(&target.moments().fresnel, &moments.fresnel, sizeof(double)) == 0);
    CHECK(target.moments().average_direction == moments.average_direction);
    const FitError judged = target.judge(m);
    const FitError alone = FitErrorEstimator(lobe, metric_points).errors(LtcDistribution(m, moments.albedo));
    CAPTURE(metric_points);
    CHECK(judged.cubed == alone.cubed);
    CHECK(judged.l2 == alone.l2);
    CHECK(judged.target_l2 == alone.target_l2);
    CHECK(judged.l2 > 0.0);
  }
}
