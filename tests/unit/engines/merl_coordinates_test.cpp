// Rusinkiewicz half/difference coordinates and the MERL grid, both ways.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_floating_point.hpp>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "pbrfit/brdf/merl_table.hpp"
#include "pbrfit/brdf/neural_brdf.hpp"
#include "pbrfit/core/random_stream.hpp"

using namespace pbrfit::brdf;
using Catch::Matchers::WithinAbs;
using pbrfit::Vector3;

namespace {

Vector3 random_upper(pbrfit::RandomStream& random) {
  const double z = random.uniform(), phi = 2.0 * std::numbers::pi * random.uniform();
  const double r = std::sqrt(1.0 - z * z);
  return {r * std::cos(phi), r * std::sin(phi), z};
}

}  // namespace

TEST_CASE("half/difference coordinates give the direction pair back") {
  pbrfit::RandomStream random(5, 0);
  for (int i = 0; i < 1000; ++i) {
    const Vector3 wi = random_upper(random), wo = random_upper(random);
    const auto back = from_half_diff(to_half_diff(wi, wo));
    CHECK((back.wi - wi).norm() < 1e-12);
    CHECK((back.wo - wo).norm() < 1e-12);
  }
  const auto normal = to_half_diff(Vector3::UnitZ(), Vector3::UnitZ());
  CHECK(normal.theta_h == 0.0);
  CHECK(normal.theta_d == 0.0);
}

TEST_CASE("the MERL grid maps cells to their centres and back, with reciprocity and clamping") {
  for (std::size_t flat : {std::size_t{0}, std::size_t{1}, std::size_t{12345}, merl_cells - 1}) {
    const MerlCell cell = merl_cell_at(flat);
    CHECK(cell.flat() == flat);
    CHECK(merl_cell_of(merl_centre_of(cell)).flat() == flat);
  }
  HalfDiff negative_phi{0.3, 0.0, 0.4, -0.5};
  HalfDiff folded{0.3, 0.0, 0.4, std::numbers::pi - 0.5};
  CHECK(merl_cell_of(negative_phi).flat() == merl_cell_of(folded).flat());
  CHECK(merl_cell_of({-1.0, 0.0, 10.0, 10.0}).theta_h == 0);
  CHECK(merl_cell_of({-1.0, 0.0, 10.0, 10.0}).theta_d == merl_theta_d - 1);
  // theta_h is sampled in sqrt space: cell 45 starts at a quarter of pi/2
  CHECK(merl_cell_of({0.25 * 0.5 * std::numbers::pi + 1e-9, 0.0, 0.1, 0.1}).theta_h == 45);
}

TEST_CASE("stored MERL values become BRDF values with the channel scales; negative ones are missing") {
  std::vector<double> stored(3 * merl_cells, 1500.0);
  stored[7] = -1.0;
  const MerlTable table = merl_table_from_stored(stored);
  CHECK(table.value(0, 0) == 1.0);
  CHECK_THAT(table.value(1, 0), WithinAbs(1.15, 1e-12));
  CHECK_THAT(table.value(2, 0), WithinAbs(1.66, 1e-12));
  CHECK_FALSE(table.measured(7));
  CHECK(table.measured_cells() == merl_cells - 1);
  CHECK(stored_from_merl_table(table)[7] < 0.0);
  CHECK_THAT(stored_from_merl_table(table)[merl_cells], WithinAbs(1500.0, 1e-9));
  std::vector<double> bad(3 * merl_cells, 0.0);
  bad[3] = -std::numeric_limits<double>::infinity();
  CHECK_THROWS_AS(MerlTable(bad), std::invalid_argument);
}

TEST_CASE("a neural stand-in with zero weights is exp(0) - 1 = 0; shapes are checked") {
  NeuralBrdfWeights w{std::vector<double>(6 * 21), std::vector<double>(21), std::vector<double>(21 * 21),
                      std::vector<double>(21), std::vector<double>(21 * 3), {0.5, 1.0, 2.0}};
  const NeuralBrdf net(w);
  const auto rgb = net.evaluate({0.2, 0.0, 0.3, 0.4});
  CHECK_THAT(rgb[0], WithinAbs(std::expm1(0.5), 1e-15));
  CHECK_THAT(rgb[2], WithinAbs(std::expm1(2.0), 1e-15));
  w.b3.pop_back();
  CHECK_THROWS_AS(NeuralBrdf(w), std::invalid_argument);
}

TEST_CASE("Interpolated MERL values match the cells at their centres, blend between them and skip gaps", "[brdf]") {
  using namespace pbrfit::brdf;
  MerlTable table;
  for (std::size_t c = 0; c < merl_cells; ++c) {
    const MerlCell cell = merl_cell_at(c);
    for (std::size_t k = 0; k < 3; ++k) table.set(k, c, double(cell.theta_h) + 0.01 * double(cell.theta_d) + double(k));
  }
  const MerlCell cell{40, 20, 30};
  const auto pair = from_half_diff(merl_centre_of(cell));
  const auto at_centre = table.interpolate(pair.wi, pair.wo);
  for (std::size_t k = 0; k < 3; ++k) CHECK(std::abs(at_centre[k] - table.value(k, cell.flat())) < 1e-9);
  // Halfway in theta_d between two cells: the mean of their values.
  HalfDiff between = merl_centre_of(cell);
  between.theta_d = (21.0 / 90.0) * 0.5 * std::numbers::pi;
  const auto halfway = from_half_diff(between);
  CHECK(std::abs(table.interpolate(halfway.wi, halfway.wo)[0] - (40.0 + 0.01 * 20.5)) < 1e-9);
  // An unmeasured neighbour drops out: the value is the measured one's.
  const MerlCell gap{40, 21, 30};
  for (std::size_t k = 0; k < 3; ++k) table.set(k, gap.flat(), std::nan(""));
  CHECK(std::abs(table.interpolate(halfway.wi, halfway.wo)[0] - (40.0 + 0.01 * 20.0)) < 1e-9);
}
