#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include "pbrfit/optimize/test_functions.hpp"

using namespace pbrfit::optimize;

TEST_CASE("Test functions are exactly 0 at their minimizer in any dimension", "[optimize]") {
  for (const TestFunction& problem : {sphere_problem, rosenbrock_problem, rastrigin_problem, ackley_problem}) {
    for (std::size_t dimension : {2u, 3u, 10u, 30u}) {
      const std::vector<double> minimizer(dimension, problem.minimizer_coordinate);
      CAPTURE(problem.name, dimension);
      CHECK(problem.evaluate(minimizer) == problem.minimum);
      CHECK(problem.lower <= problem.minimizer_coordinate);
      CHECK(problem.minimizer_coordinate <= problem.upper);
    }
  }
}

TEST_CASE("Test functions match hand-computed values away from the minimum", "[optimize]") {
  const std::vector<double> ones(4, 1.0);
  const std::vector<double> zeros(4, 0.0);
  const std::vector<double> halves(3, 0.5);
  CHECK(sphere(ones) == 4.0);
  CHECK(rosenbrock(zeros) == 3.0);                      // (1 - 0)^2 per consecutive pair
  CHECK(rosenbrock(std::vector<double>{-1.0, 1.0}) == 4.0);
  CHECK(std::abs(rastrigin(ones) - 4.0) < 1e-12);       // integer points: only the x^2 term remains
  CHECK(std::abs(rastrigin(halves) - 3 * 20.25) < 1e-12);  // 0.25 + 10 (1 - cos pi) per coordinate
  const double ackley_at_ones = 20.0 * (1.0 - std::exp(-0.2));  // cos(2 pi) = 1, so the second term is 0
  CHECK(std::abs(ackley(ones) - ackley_at_ones) < 1e-12);
}

TEST_CASE("Test functions have the customary domains", "[optimize]") {
  CHECK(rastrigin_problem.lower == -5.12);
  CHECK(rastrigin_problem.upper == 5.12);
  CHECK(ackley_problem.lower == -32.768);
  CHECK(ackley_problem.upper == 32.768);
  CHECK(rosenbrock_problem.lower == -5.0);
  CHECK(rosenbrock_problem.upper == 10.0);
}
