// Solved runs of the default fitter (pbrfit::optimize::fit) at fixed budgets, over 100 seeds. A run is
// solved when its reported value is below 1e-6; every objective evaluation counts, the polish included.
// Each row uses the default FitOptions with only the budget and the bounds set.
//   bench_optimizers [seeds]
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <span>
#include <vector>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/optimize/fit.hpp"
#include "pbrfit/optimize/test_functions.hpp"

using namespace pbrfit::optimize;

namespace {

constexpr double solved_below = 1e-6;

struct Row {
  TestFunction problem;
  std::size_t dimension;
  std::size_t budget;
  const char* goal;
};

struct Tally {
  int solved = 0;
  double evaluations_to_solve = 0.0;  // summed over solved runs: the evaluation that first went below 1e-6
  double evaluations_used = 0.0;      // summed over all runs
  double wall_seconds = 0.0;
  double cpu_seconds = 0.0;
};

Tally run_row(const Row& row, int seeds) {
  Tally tally;
  const auto wall_start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  for (int seed = 0; seed < seeds; ++seed) {
    std::size_t calls = 0;
    std::size_t first_solved = 0;
    const Objective counted = [&](std::span<const double> x) {
      const double value = row.problem.evaluate(x);
      ++calls;
      if (value < solved_below && first_solved == 0) first_solved = calls;
      return value;
    };
    FitOptions options;
    options.max_evaluations = row.budget;
    pbrfit::RandomStream random(static_cast<std::uint64_t>(seed), 0);
    const FitResult result =
        fit(counted, uniform_bounds(row.dimension, row.problem.lower, row.problem.upper), options, random);
    if (calls != result.evaluations || calls > row.budget) std::abort();  // the counts must agree
    tally.evaluations_used += static_cast<double>(calls);
    if (result.value < solved_below) {
      ++tally.solved;
      tally.evaluations_to_solve += static_cast<double>(first_solved);
    }
  }
  tally.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  tally.cpu_seconds = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  return tally;
}

}  // namespace

int main(int argc, char** argv) {
  const int seeds = argc > 1 ? std::atoi(argv[1]) : 100;
  const std::vector<Row> rows = {
      {rastrigin_problem, 5, 5'000, ">= 95"},
      {rastrigin_problem, 10, 20'000, "100"},
      {ackley_problem, 10, 20'000, "100"},
      {rosenbrock_problem, 10, 50'000, ">= 90"},
  };
  std::printf("| problem | D | domain | budget | solved (f < 1e-6) | goal | mean evals to solve | mean evals used |"
              " wall s | cpu s |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Row& row : rows) {
    const Tally tally = run_row(row, seeds);
    const double mean_to_solve = tally.solved > 0 ? tally.evaluations_to_solve / tally.solved : 0.0;
    std::printf("| %s | %zu | [%g, %g] | %zu | %d / %d | %s | %.0f | %.0f | %.2f | %.2f |\n", row.problem.name,
                row.dimension, row.problem.lower, row.problem.upper, row.budget, tally.solved, seeds, row.goal,
                mean_to_solve, tally.evaluations_used / seeds, tally.wall_seconds, tally.cpu_seconds);
  }
  return 0;
}
