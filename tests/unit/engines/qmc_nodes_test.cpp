// Weighted QMC node sets integrate known functions over boxes, the sphere and the hemisphere.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_floating_point.hpp>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "pbrfit/integrate/qmc_nodes.hpp"

using namespace pbrfit::integrate;
using Catch::Matchers::WithinAbs;

namespace {

template <class F>
double estimate(const WeightedNodes& nodes, F f) {
  double sum = 0.0;
  for (std::size_t i = 0; i < nodes.size(); ++i) sum += nodes.weights[i] * f(nodes.node(i));
  return sum;
}

}  // namespace

TEST_CASE("box nodes integrate a smooth function over a box, and their weights sum to its volume") {
  const std::vector<double> lower = {0.0, -1.0}, upper = {2.0, 1.0};
  const auto nodes = box_qmc_nodes(lower, upper, 4096);
  CHECK_THAT(estimate(nodes, [](auto) { return 1.0; }), WithinAbs(4.0, 1e-12));
  // integral of x^2 y^2 over [0, 2] x [-1, 1] = (8/3)(2/3)
  CHECK_THAT(estimate(nodes, [](auto x) { return x[0] * x[0] * x[1] * x[1]; }), WithinAbs(16.0 / 9.0, 5e-3));
  CHECK_THROWS_AS(box_qmc_nodes(std::vector<double>{1.0}, std::vector<double>{1.0}, 8), std::invalid_argument);
}

TEST_CASE("direction nodes integrate over the sphere and the hemisphere with MIS weights") {
  const double pi = std::numbers::pi;
  const auto sphere = direction_qmc_nodes(4096, false);
  const auto hemisphere = direction_qmc_nodes(4096, true);
  CHECK(sphere.size() == 8192);
  CHECK_THAT(estimate(sphere, [](auto) { return 1.0; }), WithinAbs(4.0 * pi, 2e-2));
  CHECK_THAT(estimate(hemisphere, [](auto) { return 1.0; }), WithinAbs(2.0 * pi, 1e-2));
  // integral of max(z, 0)^2 = 2 pi / 3 over either domain; z^2 over the sphere = 4 pi / 3
  CHECK_THAT(estimate(hemisphere, [](auto w) { return w[2] * w[2]; }), WithinAbs(2.0 * pi / 3.0, 5e-3));
  CHECK_THAT(estimate(sphere, [](auto w) { return w[2] * w[2]; }), WithinAbs(4.0 * pi / 3.0, 1e-2));
  for (std::size_t i = 0; i < hemisphere.size(); ++i) CHECK(hemisphere.node(i)[2] >= 0.0);
}
