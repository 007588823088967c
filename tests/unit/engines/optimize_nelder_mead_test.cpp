#include <catch2/catch_test_macros.hpp>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "pbrfit/optimize/nelder_mead.hpp"
#include "pbrfit/optimize/nelder_mead.hpp"
#include "pbrfit/optimize/test_functions.hpp"

using namespace pbrfit::optimize;

namespace {

// Wraps a test function and counts the calls.
struct Recorder {
  double (*function)(std::span<const double>);
  std::size_t calls = 0;

  Objective objective() {
    return [this](std::span<const double> x) {
      ++calls;
      return function(x);
    };
  }
};

// Rank of the edge vectors (vertex - vertex 0) restricted to the free dimensions.
long edge_rank(const std::vector<std::vector<double>>& vertices, const Bounds& bounds) {
  std::vector<std::size_t> free;
  for (std::size_t d = 0; d < bounds.dimension(); ++d) {
    if (!bounds.is_fixed(d)) free.push_back(d);
  }
  Eigen::MatrixXd edges(static_cast<long>(vertices.size() - 1), static_cast<long>(free.size()));
  for (std::size_t i = 1; i < vertices.size(); ++i) {
    for (std::size_t k = 0; k < free.size(); ++k) {
      edges(static_cast<long>(i - 1), static_cast<long>(k)) = vertices[i][free[k]] - vertices[0][free[k]];
    }
  }
  return Eigen::FullPivLU<Eigen::MatrixXd>(edges).rank();
}

}  // namespace

TEST_CASE("Nelder-Mead finds the Rosenbrock minimum from the standard start", "[optimize]") {
  Recorder recorder{rosenbrock};
  const std::vector<double> start{-1.2, 1.0};
  const auto result = nelder_mead(recorder.objective(), uniform_bounds(2, -2.048, 2.048), start, {}, 2000);
  CHECK(result.stop == StopReason::converged);
  CHECK(result.best.value < 1e-12);
  CHECK(std::abs(result.best.x[0] - 1.0) < 1e-6);
  CHECK(std::abs(result.best.x[1] - 1.0) < 1e-6);
  CHECK(result.evaluations == recorder.calls);
  CHECK(result.evaluations < 1000);
}

TEST_CASE("The starting simplex is never degenerate and stays in the box", "[optimize]") {
  Bounds bounds{{-1.0, 0.0, 2.0, -3.0}, {1.0, 10.0, 2.0, 3.0}};  // dimension 2 is fixed
  const std::vector<std::vector<double>> starts{{0.0, 5.0, 2.0, 0.0},     // interior
                                                {1.0, 10.0, 2.0, 3.0},    // upper corner
                                                {-1.0, 0.0, 2.0, -3.0},   // lower corner
                                                {0.999, 9.99, 2.0, 2.9},  // near the upper corner
                                                {7.0, -4.0, 9.0, 1.0}};   // outside: clamped
  for (double step : {1e-300, 1e-9, 0.1, 0.6, 5.0}) {
    for (const auto& start : starts) {
      const std::vector<double> steps(4, step);
      const auto vertices = starting_simplex(bounds, start, steps);
      CAPTURE(step, start);
      REQUIRE(vertices.size() == 4);  // three free dimensions
      for (const auto& vertex : vertices) CHECK(contains(bounds, vertex));
      CHECK(edge_rank(vertices, bounds) == 3);
    }
  }
  CHECK_THROWS(starting_simplex(bounds, starts[0], std::vector<double>(4, 0.0)));
}

TEST_CASE("Every point Nelder-Mead evaluates respects the bounds", "[optimize]") {
  std::vector<std::vector<double>> points;
  const Objective outside_minimum = [&](std::span<const double> x) {
    points.emplace_back(x.begin(), x.end());
    return (x[0] - 3.0) * (x[0] - 3.0) + (x[1] + 4.0) * (x[1] + 4.0) + x[2] * x[2];
  };
  const Bounds bounds = uniform_bounds(3, -1.0, 1.0);
  const auto result = nelder_mead(outside_minimum, bounds, std::vector<double>{0.0, 0.0, 0.5}, {}, 3000);
  CHECK(points.size() > 100);
  for (const auto& point : points) CHECK(contains(bounds, point));
  CHECK(std::abs(result.best.x[0] - 1.0) < 1e-9);  // the minimum over the box is on its corner
  CHECK(std::abs(result.best.x[1] + 1.0) < 1e-9);
  CHECK(std::abs(result.best.x[2]) < 1e-6);
}

TEST_CASE("Nelder-Mead counts every evaluation and stops exactly at the budget", "[optimize]") {
  for (std::size_t budget : {1u, 2u, 5u, 37u, 400u}) {
    Recorder recorder{rosenbrock};
    const auto result = nelder_mead(recorder.objective(), uniform_bounds(4, -5.0, 10.0),
                                    std::vector<double>(4, -2.0), {}, budget);
    CAPTURE(budget);
    CHECK(recorder.calls == budget);  // Rosenbrock 4-D does not converge within 400 evaluations
    CHECK(result.evaluations == budget);
    CHECK(result.stop == StopReason::budget);
  }
}

TEST_CASE("Restarts happen when the simplex collapses and keep improving", "[optimize]") {
  NelderMeadOptions coarse;  // a loose collapse test: the first collapse comes long before the minimum
  coarse.x_tolerance = 1e-3;
  coarse.f_tolerance_relative = 1.0;
  NelderMeadOptions single = coarse;
  single.max_restarts = 0;
  const std::vector<double> start(6, -1.0);
  const Bounds bounds = uniform_bounds(6, -5.0, 10.0);
  const auto once = nelder_mead(rosenbrock, bounds, start, single, 100'000);
  const auto restarted = nelder_mead(rosenbrock, bounds, start, coarse, 100'000);
  CHECK(once.restarts == 0);
  CHECK(once.stop == StopReason::converged);
  CHECK(once.best.value > 0.1);
  CHECK(restarted.restarts >= 2);
  CHECK(restarted.stop == StopReason::converged);
  CHECK(restarted.best.value < 1e-10);
}

TEST_CASE("A warm start near the minimum needs fewer evaluations", "[optimize]") {
  NelderMeadOptions options;
  options.target = 1e-10;
  const Bounds bounds = uniform_bounds(5, -5.0, 10.0);
  const auto cold = nelder_mead(rosenbrock, bounds, std::vector<double>(5, -3.0), options, 50'000);
  const auto warm = nelder_mead(rosenbrock, bounds, std::vector<double>{1.01, 0.99, 1.0, 1.02, 1.03}, options, 50'000);
  REQUIRE(cold.stop == StopReason::target);
  REQUIRE(warm.stop == StopReason::target);
  CHECK(warm.evaluations < cold.evaluations / 2);
}

TEST_CASE("Multi-start Nelder-Mead keeps the best run", "[optimize]") {
  const Bounds bounds = uniform_bounds(2, -5.12, 5.12);
  const std::vector<std::vector<double>> starts{{3.1, -2.2}, {0.3, 0.2}, {-4.0, 4.0}};
  NelderMeadOptions options;
  options.initial_step = 0.01;  // stays in the basin of each start
  Evaluator evaluator(rastrigin, 100'000);
  const auto multi = multi_start_nelder_mead(evaluator, bounds, starts, options);
  double best_single = std::numeric_limits<double>::infinity();
  std::size_t total = 0;
  for (const auto& start : starts) {
    const auto single = nelder_mead(rastrigin, bounds, start, options, 100'000);
    best_single = std::min(best_single, single.best.value);
    total += single.evaluations;
  }
  CHECK(multi.starts_run == 3);
  CHECK(multi.winning_start == 1);
  CHECK(multi.best.value == best_single);
  CHECK(multi.best.value < 1e-12);
  CHECK(multi.evaluations == total);
  CHECK(evaluator.used() == total);
}

TEST_CASE("Nelder-Mead tightens the tolerance as the simplex shrinks and reports at the final one", "[optimize]") {
  std::vector<double> tolerances;
  const Objective noisy = [&](std::span<const double> x, double tolerance) {
    tolerances.push_back(tolerance);
    return sphere(x) + tolerance;  // the error an integrator at this tolerance could make
  };
  const ToleranceSchedule schedule{1e-2, 1e-8, 1e-4, 4};
  const auto result = nelder_mead(noisy, uniform_bounds(3, -1.0, 1.0), std::vector<double>{0.5, -0.3, 0.2}, {},
                                  5000, schedule);
  REQUIRE(tolerances.size() == result.evaluations);
  for (std::size_t i = 1; i < tolerances.size(); ++i) CHECK(tolerances[i] <= tolerances[i - 1]);
  CHECK(tolerances.front() == 1e-2);
  for (double level : {1e-2, 1e-4, 1e-6, 1e-8}) {
    CAPTURE(level);
    // every level is visited, each time with the whole simplex re-measured
    const auto near_level = [&](double tolerance) { return std::abs(tolerance / level - 1.0) < 1e-9; };
    CHECK(std::count_if(tolerances.begin(), tolerances.end(), near_level) >= 4);
  }
  CHECK(result.best.tolerance == 1e-8);
  CHECK(result.best.value == sphere(result.best.x) + 1e-8);
}
