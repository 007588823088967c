#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <vector>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/optimize/differential_evolution.hpp"
#include "pbrfit/optimize/test_functions.hpp"

using namespace pbrfit::optimize;
using pbrfit::RandomStream;

namespace {

DeResult run(const Objective& objective, const Bounds& bounds, const DeOptions& options, std::size_t budget,
             std::uint64_t seed, std::span<const std::vector<double>> seeds = {}) {
  RandomStream random(seed, 0);
  return differential_evolution(objective, bounds, options, budget, random, seeds);
}

bool bitwise_equal(const Candidate& a, const Candidate& b) {
  return a.x.size() == b.x.size() && std::memcmp(a.x.data(), b.x.data(), a.x.size() * sizeof(double)) == 0 &&
         std::memcmp(&a.value, &b.value, sizeof(double)) == 0;
}

}  // namespace

TEST_CASE("The default population follows the course: min(40, 10 D), at least 5", "[optimize]") {
  DeOptions options;
  CHECK(population_size_for(options, 1) == 10);
  CHECK(population_size_for(options, 3) == 30);
  CHECK(population_size_for(options, 12) == 40);
  options.population_size = 3;
  CHECK(population_size_for(options, 12) == 5);
  options.population_size = 64;
  CHECK(population_size_for(options, 2) == 64);
}

TEST_CASE("DE/rand/1/bin and DE/best/1/bin both solve easy problems", "[optimize]") {
  for (DeStrategy strategy : {DeStrategy::rand_1, DeStrategy::best_1, DeStrategy::current_to_pbest}) {
    DeOptions options;
    options.strategy = strategy;
    options.crossover = 0.9;
    options.target = 1e-10;
    const auto on_sphere = run(sphere, uniform_bounds(4, -5.12, 5.12), options, 40'000, 1);
    const auto on_rosenbrock = run(rosenbrock, uniform_bounds(2, -2.048, 2.048), options, 40'000, 2);
    CAPTURE(static_cast<int>(strategy), on_sphere.best.value, on_rosenbrock.best.value);
    CHECK(on_sphere.stop == StopReason::target);
    CHECK(on_rosenbrock.stop == StopReason::target);
  }
}

TEST_CASE("Every weight control solves the sphere", "[optimize]") {
  for (WeightControl control : {WeightControl::fixed, WeightControl::dither_per_generation,
                                WeightControl::dither_per_vector, WeightControl::self_adaptive}) {
    DeOptions options;
    options.control = control;
    options.target = 1e-10;
    const auto result = run(sphere, uniform_bounds(3, -5.12, 5.12), options, 30'000, 3);
    CAPTURE(static_cast<int>(control));
    CHECK(result.stop == StopReason::target);
  }
}

TEST_CASE("DE is bitwise reproducible for a seed and differs across seeds", "[optimize]") {
  DeOptions options;
  options.control = WeightControl::self_adaptive;
  const Bounds bounds = uniform_bounds(5, -5.12, 5.12);
  const auto first = run(rastrigin, bounds, options, 3000, 11);
  const auto second = run(rastrigin, bounds, options, 3000, 11);
  const auto other = run(rastrigin, bounds, options, 3000, 12);
  CHECK(bitwise_equal(first.best, second.best));
  CHECK(first.evaluations == second.evaluations);
  REQUIRE(first.population.size() == second.population.size());
  for (std::size_t i = 0; i < first.population.size(); ++i) {
    CHECK(bitwise_equal(first.population[i], second.population[i]));
  }
  CHECK_FALSE(bitwise_equal(first.best, other.best));
}

TEST_CASE("DE counts every evaluation and spends exactly its budget", "[optimize]") {
  for (std::size_t budget : {1u, 7u, 40u, 41u, 1234u}) {
    std::size_t calls = 0;
    const Objective counted = [&](std::span<const double> x) {
      ++calls;
      return rastrigin(x);
    };
    const auto result = run(counted, uniform_bounds(6, -5.12, 5.12), DeOptions{}, budget, 5);
    CAPTURE(budget);
    CHECK(calls == budget);
    CHECK(result.evaluations == budget);
    CHECK(result.stop == StopReason::budget);
  }
}

TEST_CASE("Both bound handlings keep every trial in the box", "[optimize]") {
  for (BoundHandling handling : {BoundHandling::clamp, BoundHandling::reinitialize}) {
    const Bounds bounds{{-1.0, 2.0, 0.0}, {1.0, 3.0, 0.0}};  // the third dimension is fixed
    bool all_inside = true;
    const Objective edge_minimum = [&](std::span<const double> x) {
      all_inside = all_inside && contains(bounds, x);
      return (x[0] - 5.0) * (x[0] - 5.0) + (x[1] - 2.0) * (x[1] - 2.0);
    };
    DeOptions options;
    options.bound_handling = handling;
    options.weight = 0.9;
    const auto result = run(edge_minimum, bounds, options, 2000, 6);
    CAPTURE(static_cast<int>(handling));
    CHECK(all_inside);
    CHECK(std::abs(result.best.x[0] - 1.0) < 1e-3);
    CHECK(std::abs(result.best.x[1] - 2.0) < 1e-3);
    CHECK(result.best.x[2] == 0.0);
  }
}

TEST_CASE("Seeded points warm-start the population", "[optimize]") {
  DeOptions options;
  options.target = 1e-8;
  const Bounds bounds = uniform_bounds(4, -5.0, 10.0);
  const std::vector<std::vector<double>> near_minimum{{1.001, 1.002, 1.004, 1.008}};
  const auto cold = run(rosenbrock, bounds, options, 200'000, 7);
  const auto warm = run(rosenbrock, bounds, options, 200'000, 7, near_minimum);
  REQUIRE(cold.stop == StopReason::target);
  REQUIRE(warm.stop == StopReason::target);
  CHECK(warm.evaluations < cold.evaluations);

  const std::vector<std::vector<double>> exact{{1.0, 1.0, 1.0, 1.0}};
  const auto instant = run(rosenbrock, bounds, options, 200'000, 7, exact);
  CHECK(instant.stop == StopReason::target);
  CHECK(instant.evaluations == population_size_for(options, 4));  // the initial population only
  CHECK(instant.best.x == exact[0]);
}

TEST_CASE("DE stops on stagnation, spread and the generation limit", "[optimize]") {
  const Bounds bounds = uniform_bounds(2, -1.0, 1.0);
  SECTION("a flat function stagnates after the configured generations") {
    DeOptions options;
    options.stagnation_generations = 7;
    const auto result = run([](std::span<const double>) { return 1.0; }, bounds, options, 100'000, 8);
    CHECK(result.stop == StopReason::stagnation);
    CHECK(result.generations == 7);
    CHECK(result.evaluations == 8 * population_size_for(options, 2));
  }
  SECTION("a converging population stops on its spread") {
    DeOptions options;
    options.min_spread = 1e-3;
    const auto result = run(sphere, bounds, options, 100'000, 9);
    CHECK(result.stop == StopReason::spread);
    for (const Candidate& member : result.population) CHECK(std::abs(member.x[0] - result.best.x[0]) < 2e-3);
  }
  SECTION("the generation limit") {
    DeOptions options;
    options.max_generations = 3;
    const auto result = run(sphere, bounds, options, 100'000, 10);
    CHECK(result.stop == StopReason::iteration_limit);
    CHECK(result.evaluations == 4 * population_size_for(options, 2));
  }
}

TEST_CASE("DE tightens the tolerance with the population spread and reports at the final one", "[optimize]") {
  std::vector<double> tolerances;
  const Objective noisy = [&](std::span<const double> x, double tolerance) {
    tolerances.push_back(tolerance);
    return sphere(x) + tolerance;
  };
  const ToleranceSchedule schedule{1e-2, 1e-8, 1e-3, 3};
  RandomStream random(13, 0);
  const auto result = differential_evolution(noisy, uniform_bounds(3, -1.0, 1.0), DeOptions{}, 6000, random, {},
                                             schedule);
  REQUIRE(tolerances.size() == result.evaluations);
  for (std::size_t i = 1; i < tolerances.size(); ++i) CHECK(tolerances[i] <= tolerances[i - 1]);
  const auto at = [&](double level) {
    const auto near_level = [&](double tolerance) { return std::abs(tolerance / level - 1.0) < 1e-9; };
    return std::count_if(tolerances.begin(), tolerances.end(), near_level);
  };
  CHECK(tolerances.front() == 1e-2);
  CHECK(at(1e-2) >= 30);  // at least the initial population
  CHECK(at(1e-5) > 30);   // the middle level: spread between 10^-1.5 and 1e-3
  CHECK(at(1e-8) > 30);   // the search itself reached the final level, not just the re-measurement
  CHECK(at(1e-2) + at(1e-5) + at(1e-8) == static_cast<long>(tolerances.size()));
  CHECK(result.best.tolerance == 1e-8);
  CHECK(result.best.value == sphere(result.best.x) + 1e-8);
}

namespace {

// The initial population (the first `size` evaluations) and the first generation's trials (the next
// `size`), in member order, as the objective saw them.
struct FirstGeneration {
  std::vector<std::vector<double>> members;
  std::vector<double> values;
  std::vector<std::vector<double>> trials;
};

FirstGeneration first_generation(const DeOptions& options, const Bounds& bounds) {
  const std::size_t size = population_size_for(options, bounds.dimension());
  std::vector<std::vector<double>> points;
  std::vector<double> values;
  const Objective recorded = [&](std::span<const double> x) {
    points.emplace_back(x.begin(), x.end());
    values.push_back(sphere(x));
    return values.back();
  };
  RandomStream random(17, 0);
  differential_evolution(recorded, bounds, options, 2 * size, random);
  return {{points.begin(), points.begin() + size}, {values.begin(), values.begin() + size},
          {points.begin() + size, points.end()}};
}

// True when trial == clamp(base + F (plus - minus)) in every coordinate for some donors plus != minus,
// both different from the target (and from the base when it is a random member too).
bool is_mutant_of(const FirstGeneration& generation, const Bounds& bounds, std::size_t target, std::size_t base,
                  double weight, bool base_is_random) {
  const std::size_t size = generation.members.size();
  const auto& trial = generation.trials[target];
  for (std::size_t plus = 0; plus < size; ++plus) {
    for (std::size_t minus = 0; minus < size; ++minus) {
      if (plus == minus || plus == target || minus == target) continue;
      if (base_is_random && (plus == base || minus == base)) continue;
      bool matches = true;
      for (std::size_t d = 0; d < trial.size() && matches; ++d) {
        const double mutant = generation.members[base][d] +
                              weight * (generation.members[plus][d] - generation.members[minus][d]);
        matches = trial[d] == std::clamp(mutant, bounds.lower[d], bounds.upper[d]);
      }
      if (matches) return true;
    }
  }
  return false;
}

}  // namespace

TEST_CASE("CR = 0 crosses over exactly one forced dimension per trial", "[optimize]") {
  DeOptions options;
  options.crossover = 0.0;
  const Bounds bounds = uniform_bounds(4, -1.0, 1.0);
  const FirstGeneration generation = first_generation(options, bounds);
  for (std::size_t i = 0; i < generation.trials.size(); ++i) {
    int changed = 0;
    for (std::size_t d = 0; d < 4; ++d) changed += generation.trials[i][d] != generation.members[i][d] ? 1 : 0;
    CAPTURE(i);
    CHECK(changed == 1);
  }
}

TEST_CASE("With CR = 1 a trial is the mutant of its strategy", "[optimize]") {
  const Bounds bounds = uniform_bounds(3, -1.0, 1.0);
  DeOptions options;
  options.crossover = 1.0;
  options.population_size = 8;
  SECTION("DE/rand/1: x_r1 + F (x_r2 - x_r3), all distinct from the target") {
    const FirstGeneration generation = first_generation(options, bounds);
    for (std::size_t i = 0; i < 8; ++i) {
      bool found = false;
      for (std::size_t base = 0; base < 8 && !found; ++base) {
        found = base != i && is_mutant_of(generation, bounds, i, base, options.weight, true);
      }
      CAPTURE(i);
      CHECK(found);
    }
  }
  SECTION("DE/best/1: the base is the best member") {
    options.strategy = DeStrategy::best_1;
    const FirstGeneration generation = first_generation(options, bounds);
    const auto best = static_cast<std::size_t>(
        std::min_element(generation.values.begin(), generation.values.end()) - generation.values.begin());
    for (std::size_t i = 0; i < 8; ++i) {
      CAPTURE(i);
      CHECK(is_mutant_of(generation, bounds, i, best, options.weight, false));
    }
  }
}
