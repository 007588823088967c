#include <algorithm>
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <cstddef>

#include "gp_test_support.hpp"
#include "pbrfit/gp/evolve.hpp"
#include "pbrfit/gp/expression_parser.hpp"
#include "pbrfit/gp/expression_printer.hpp"
#include "pbrfit/gp/program_bytes.hpp"

using namespace pbrfit::gp;
using pbrfit::RandomStream;

namespace {

const Dataset& square_plus_x() {
  static const Dataset dataset = gp_test::sampled_dataset(20, 1, -1.0, 1.0, [](auto x) { return x[0] * x[0] + x[0]; });
  return dataset;
}

EvolveOptions small_run() {
  EvolveOptions options;
  options.population_size = 100;
  options.fitness.precision = Precision::float64;
  options.target_error = 1e-12;
  return options;
}

EvolveResult run(const EvolveOptions& options, std::uint64_t seed, std::size_t generations,
                 const Dataset& data = square_plus_x()) {
  const Population start = random_population(options, RandomStream(seed, 0));
  return evolve(start, {}, generations, options, data, RandomStream(seed, 1));
}

bool mutually_non_dominated(const std::vector<ArchiveEntry>& entries, std::size_t objectives) {
  for (const auto& a : entries) {
    for (const auto& b : entries) {
      if (dominates(a.fitness, b.fitness, objectives)) return false;
    }
  }
  return true;
}

}  // namespace

TEST_CASE("A small symbolic regression, x^2 + x on 20 points, is solved within a small budget", "[gp]") {
  for (SelectionScheme scheme : {SelectionScheme::pareto, SelectionScheme::tournament}) {
    EvolveOptions options = small_run();
    options.selection = scheme;
    options.tournament_size = scheme == SelectionScheme::pareto ? 2 : 4;
    options.max_evaluations = 20'000;
    int solved = 0;
    for (std::uint64_t seed = 0; seed < 5; ++seed) {
      const EvolveResult result = run(options, seed, 1000);
      CHECK(result.stats.evaluations <= options.max_evaluations);
      solved += result.stats.reached_target;
    }
    CAPTURE(static_cast<int>(scheme));
    CHECK(solved == 5);
  }
}

TEST_CASE("Evolution is bitwise reproducible for a seed key and differs across keys", "[gp]") {
  EvolveOptions options = small_run();
  options.target_error = -1.0;  // run every generation, even once x^2 + x is found
  options.shape.constant_probability = 0.2;
  options.constant_fits_per_generation = 2;
  const EvolveResult first = run(options, 3, 8);
  const EvolveResult again = run(options, 3, 8);
  const EvolveResult other = run(options, 4, 8);
  CHECK(population_to_bytes(first.population) == population_to_bytes(again.population));
  CHECK(archive_to_bytes(first.archive_additions) == archive_to_bytes(again.archive_additions));
  CHECK(first.stats.evaluations == again.stats.evaluations);
  CHECK(first.stats.generations == 8);
  CHECK(population_to_bytes(first.population) != population_to_bytes(other.population));
}

TEST_CASE("An epoch carried through bytes continues exactly as one kept in memory", "[gp]") {
  const EvolveOptions options = small_run();
  const EvolveResult epoch = run(options, 5, 3);
  const auto emigrants = pick_emigrants(epoch.population, 3, options);
  const Population island = population_from_bytes(population_to_bytes(epoch.population), 1);
  const auto migrants = individuals_from_bytes(individuals_to_bytes(emigrants), 1);
  const RandomStream next(5, 2);
  const EvolveResult in_memory = evolve(epoch.population, emigrants, 3, options, square_plus_x(), next);
  const EvolveResult from_bytes = evolve(island, migrants, 3, options, square_plus_x(), next);
  CHECK(population_to_bytes(in_memory.population) == population_to_bytes(from_bytes.population));
  CHECK(in_memory.population.generation == epoch.population.generation + in_memory.stats.generations);
}

TEST_CASE("The budget caps every evaluation, constant fitting included", "[gp]") {
  EvolveOptions options = small_run();
  options.target_error = 0.0;
  options.shape.constant_probability = 0.5;
  options.constant_fits_per_generation = 5;
  for (std::size_t budget : {std::size_t{1}, std::size_t{99}, std::size_t{150}, std::size_t{1234}}) {
    options.max_evaluations = budget;
    const EvolveResult result = run(options, 6, 1000);
    CAPTURE(budget);
    CHECK(result.stats.evaluations <= budget);
    CHECK(result.stats.budget_exhausted);
    CHECK(result.stats.constant_fit_evaluations <= result.stats.evaluations);
    for (const Individual& member : result.population.members) CHECK(member.fitness.evaluated);
  }
}

TEST_CASE("Constant fitting inside evolution finds fitted constants", "[gp]") {
  const Dataset line = gp_test::sampled_dataset(30, 1, -2.0, 2.0, [](auto x) { return 2.75 * x[0] - 0.4; });
  EvolveOptions options = small_run();
  options.target_error = 1e-9;
  options.shape.constant_probability = 0.3;
  options.constant_fits_per_generation = 3;
  options.max_evaluations = 30'000;
  const EvolveResult result = run(options, 7, 200, line);
  CHECK(result.stats.reached_target);
  CHECK(result.stats.constant_fit_evaluations > 0);
}

TEST_CASE("Archive additions are non-dominated and migrants can take over an island", "[gp]") {
  EvolveOptions options = small_run();
  options.piecewise_objective = true;
  options.shape.operators = all_operators();
  options.target_error = 0.0;
  const EvolveResult result = run(options, 8, 5);
  REQUIRE_FALSE(result.archive_additions.empty());
  CHECK(mutually_non_dominated(result.archive_additions, 3));
  for (const ArchiveEntry& entry : result.archive_additions) CHECK(entry.generation <= result.population.generation);
  const auto exact = std::get<ParsedExpression>(parse_expression("x * x + x", {{"x"}, {}})).program;
  const std::vector<Individual> migrant{{exact, {}, 0}};
  options.piecewise_objective = false;
  options.target_error = 1e-12;
  const EvolveResult joined = evolve(result.population, migrant, 5, options, square_plus_x(), RandomStream(8, 3));
  CHECK(joined.stats.generations == 0);  // the migrant already reaches the target
  CHECK(joined.stats.reached_target);
  // The first emigrant is the most accurate front member: the migrant, or an equally exact one such as
  // fma(x, x, x), which the island may already hold.
  const Individual best = pick_emigrants(joined.population, 1, options)[0];
  CAPTURE(print_expression(best.program, {{"x"}, {}}));
  CHECK(best.fitness.error <= 1e-12);
  CHECK(best.fitness.cost <= 2.0);
}

TEST_CASE("Invalid options and programs are refused up front", "[gp]") {
  EvolveOptions options = small_run();
  options.population_size = 1;
  CHECK_THROWS_AS(run(options, 9, 1), std::invalid_argument);
  options = small_run();
  options.shape.input_count = 2;  // the dataset has one input
  CHECK_THROWS_AS(run(options, 9, 1), std::invalid_argument);
  options = small_run();
  Population island = random_population(options, RandomStream(9, 0));
  island.members[0].program.code[0].operands[0] = input_operand(5);
  CHECK_THROWS_AS(evolve(island, {}, 1, options, square_plus_x(), RandomStream(9, 1)), std::invalid_argument);
}
