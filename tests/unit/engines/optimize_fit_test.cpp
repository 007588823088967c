#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/optimize/fit.hpp"
#include "pbrfit/optimize/fit_parameters.hpp"
#include "pbrfit/optimize/test_functions.hpp"

using namespace pbrfit::optimize;
using pbrfit::RandomStream;

namespace {

FitResult fit_with_seed(const Objective& objective, const Bounds& bounds, const FitOptions& options,
                        std::uint64_t seed, std::span<const std::vector<double>> warm_starts = {}) {
  RandomStream random(seed, 0);
  return fit(objective, bounds, options, random, warm_starts);
}

FitOptions with_budget(std::size_t budget) {
  FitOptions options;
  options.max_evaluations = budget;
  return options;
}

}  // namespace

TEST_CASE("The default fitter solves multimodal and valley problems", "[optimize]") {
  const auto rastrigin_5d = fit_with_seed(rastrigin, uniform_bounds(5, -5.12, 5.12), with_budget(5000), 1);
  const auto rosenbrock_4d = fit_with_seed(rosenbrock, uniform_bounds(4, -5.0, 10.0), with_budget(20'000), 2);
  const auto ackley_3d = fit_with_seed(ackley, uniform_bounds(3, -32.768, 32.768), with_budget(5000), 3);
  CHECK(rastrigin_5d.value < 1e-8);
  CHECK(rosenbrock_4d.value < 1e-8);
  CHECK(ackley_3d.value < 1e-8);
  CHECK(rosenbrock_4d.phase == FitPhase::polish);  // DE finds the valley, Nelder-Mead its bottom
  CHECK(std::abs(rosenbrock_4d.x[3] - 1.0) < 1e-4);
}

TEST_CASE("The fitter's budget is a hard cap on every evaluation, polish included", "[optimize]") {
  for (std::size_t budget : {1u, 2u, 9u, 150u, 1000u, 7000u}) {
    for (const ToleranceSchedule& schedule : {ToleranceSchedule{}, ToleranceSchedule{1e-2, 1e-6, 1e-2, 3}}) {
      std::size_t calls = 0;
      const Objective counted = [&](std::span<const double> x) {
        ++calls;
        return rosenbrock(x);
      };
      FitOptions options = with_budget(budget);
      options.tolerance = schedule;
      options.stall_rounds = 1000;  // keep restarting until the budget is gone
      const auto result = fit_with_seed(counted, uniform_bounds(3, -5.0, 10.0), options, 4);
      CAPTURE(budget, schedule.start);
      CHECK(result.evaluations == calls);
      CHECK(calls <= budget);
      // The evaluation held back for re-measuring at the final tolerance goes unused when the best was
      // already measured there.
      CHECK(calls >= (schedule.is_constant() ? budget : budget - 1));
      CHECK(result.stop == StopReason::budget);
      CHECK(result.x.size() == 3);
    }
  }
}

TEST_CASE("The fitter is bitwise reproducible for a seed and differs across seeds", "[optimize]") {
  const Bounds bounds = uniform_bounds(4, -5.12, 5.12);
  const auto first = fit_with_seed(rastrigin, bounds, with_budget(1500), 21);
  const auto second = fit_with_seed(rastrigin, bounds, with_budget(1500), 21);
  const auto other = fit_with_seed(rastrigin, bounds, with_budget(1500), 22);
  CHECK(std::memcmp(first.x.data(), second.x.data(), 4 * sizeof(double)) == 0);
  CHECK(std::memcmp(&first.value, &second.value, sizeof(double)) == 0);
  CHECK(first.evaluations == second.evaluations);
  CHECK(first.rounds == second.rounds);
  CHECK(std::memcmp(first.x.data(), other.x.data(), 4 * sizeof(double)) != 0);
}

TEST_CASE("A warm start from a good point converges in fewer evaluations", "[optimize]") {
  FitOptions options = with_budget(100'000);
  options.target = 1e-10;
  const Bounds bounds = uniform_bounds(6, -5.0, 10.0);
  const std::vector<std::vector<double>> near_minimum{{1.01, 1.02, 1.03, 1.05, 1.1, 1.2}};
  const auto cold = fit_with_seed(rosenbrock, bounds, options, 5);
  const auto warm = fit_with_seed(rosenbrock, bounds, options, 5, near_minimum);
  REQUIRE(cold.stop == StopReason::target);
  REQUIRE(warm.stop == StopReason::target);
  CHECK(warm.evaluations < cold.evaluations / 2);
}

TEST_CASE("Cooperative accuracy: coarse while exploring, final for the polish and the result", "[optimize]") {
  std::vector<double> tolerances;
  const Objective integrated = [&](std::span<const double> x, double tolerance) {
    tolerances.push_back(tolerance);
    return rastrigin(x) + tolerance;  // the bias a cubature at this tolerance might leave
  };
  FitOptions options = with_budget(4000);
  options.tolerance = ToleranceSchedule{1e-2, 1e-9, 3e-2, 3};
  const auto result = fit_with_seed(integrated, uniform_bounds(3, -5.12, 5.12), options, 6);
  REQUIRE(tolerances.size() == result.evaluations);
  for (std::size_t i = 1; i < tolerances.size(); ++i) CHECK(tolerances[i] <= tolerances[i - 1]);
  CHECK(tolerances.front() == 1e-2);
  CHECK(tolerances.back() == 1e-9);
  const auto final_count = std::count(tolerances.begin(), tolerances.end(), 1e-9);
  CHECK(final_count > 50);  // the polish, not only the re-measurement
  CHECK(static_cast<std::size_t>(final_count) + 100 < tolerances.size());  // DE explored coarsely
  CHECK(result.value == rastrigin(result.x) + 1e-9);
}

TEST_CASE("Fitting in a parameter space: the objective sees model parameters", "[optimize]") {
  // A lobe amplitude * exp(-sharpness (1 - cos(angle - theta))) sampled at a few angles, with a scale-like
  // sharpness (log domain) and an angle (cosine domain), as in section 7.6.
  const double true_amplitude = 2.5;
  const double true_sharpness = 40.0;
  const double true_theta = 0.6;
  const auto lobe = [](double amplitude, double sharpness, double theta, double angle) {
    return amplitude * std::exp(-sharpness * (1.0 - std::cos(angle - theta)));
  };
  bool inside = true;
  const ParameterSpace space({{"amplitude", 0.1, 10.0, Transform::log},
                              {"sharpness", 1.0, 1000.0, Transform::log},
                              {"theta", 0.0, std::numbers::pi / 2, Transform::cosine}});
  const auto misfit = [&](std::span<const double> p) {
    inside = inside && contains(space.model_bounds(), p);
    double sum = 0.0;
    for (int k = 0; k <= 20; ++k) {
      const double angle = 0.05 * k;
      const double difference = lobe(p[0], p[1], p[2], angle) - lobe(true_amplitude, true_sharpness, true_theta, angle);
      sum += difference * difference;
    }
    return sum;
  };
  RandomStream random(7, 0);
  const auto result = fit(misfit, space, with_budget(6000), random);
  CHECK(inside);
  CHECK(std::abs(result.x[0] - true_amplitude) < 1e-5);
  CHECK(std::abs(result.x[1] - true_sharpness) < 1e-3);
  CHECK(std::abs(result.x[2] - true_theta) < 1e-6);
  CHECK(result.value == misfit(result.x));
}

TEST_CASE("Fixed dimensions keep their value; a fully fixed box costs one evaluation", "[optimize]") {
  bool fixed_kept = true;
  const Objective shifted_sphere = [&](std::span<const double> x) {
    fixed_kept = fixed_kept && x[1] == 0.25;
    return (x[0] - 0.5) * (x[0] - 0.5) + (x[2] + 0.5) * (x[2] + 0.5);
  };
  const Bounds partly_fixed{{-1.0, 0.25, -1.0}, {1.0, 0.25, 1.0}};
  const auto result = fit_with_seed(shifted_sphere, partly_fixed, with_budget(3000), 8);
  CHECK(fixed_kept);
  CHECK(result.value < 1e-12);

  std::size_t calls = 0;
  const Objective counted = [&](std::span<const double> x) {
    ++calls;
    return x[0] + x[1];
  };
  const auto fixed = fit_with_seed(counted, Bounds{{2.0, 3.0}, {2.0, 3.0}}, with_budget(3000), 9);
  CHECK(calls == 1);
  CHECK(fixed.evaluations == 1);
  CHECK(fixed.value == 5.0);
  CHECK(fixed.x == std::vector<double>{2.0, 3.0});
}

TEST_CASE("The fitter rejects malformed input", "[optimize]") {
  RandomStream random(10, 0);
  CHECK_THROWS_AS(fit(sphere, Bounds{{0.0}, {-1.0}}, FitOptions{}, random), std::invalid_argument);
  CHECK_THROWS_AS(fit(sphere, Bounds{{}, {}}, FitOptions{}, random), std::invalid_argument);
  const std::vector<std::vector<double>> wrong_size{{0.0, 0.0, 0.0}};
  CHECK_THROWS_AS(fit(sphere, uniform_bounds(2, -1.0, 1.0), FitOptions{}, random, wrong_size), std::invalid_argument);
  FitOptions loosening;
  loosening.tolerance = ToleranceSchedule{1e-6, 1e-3, 1e-3, 2};
  CHECK_THROWS_AS(fit(sphere, uniform_bounds(2, -1.0, 1.0), loosening, random), std::invalid_argument);
}
