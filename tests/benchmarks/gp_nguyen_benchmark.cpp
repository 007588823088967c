// Exact recovery of Nguyen-1..8 by single-process runs of the GP engine (evolve() on a ring of islands
// inside one process, as the symbolic-regression job kind runs them across ranks). Koza's function set
// (+ - * / sin cos exp log), no constants; 20 uniform training points in [-1, 1] (Nguyen-1..6), [0, 2]
// (Nguyen-7) or [0, 4] (Nguyen-8). A run stops once a program reaches a training RMSE below 1e-12 that
// also has an RMSE below 1e-9 on 10,000 fresh points of the training range (exact recovery), or when its
// evaluation budget is spent.
//   bench_gp_nguyen [seeds=10] [budget_millions=40] [first_problem=1] [last_problem=8]
// Every row uses nguyen_options(): the engine's EvolveOptions defaults (NSGA-II on error and cost,
// population 500, crossover 0.9 (half subgraph, half string), mutation 0.5, programs of at most 32
// instructions, restart of an island after 10 generations without improvement) with only the operators,
// double precision and the target set; 4 islands in a ring, the best emigrant moves every 10 generations.
// Training data, fresh points and every island's stream are keyed by the seed: a row is reproducible.
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <vector>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/gp/batch_interpreter.hpp"
#include "pbrfit/gp/evolve.hpp"
#include "pbrfit/gp/expression_printer.hpp"

using namespace pbrfit::gp;

namespace {

struct Problem {
  const char* name;
  double lower;
  double upper;
  std::function<double(double)> f;
};

const std::vector<Problem>& nguyen() {
  static const std::vector<Problem> problems{
      {"Nguyen-1", -1, 1, [](double x) { return x * x * x + x * x + x; }},
      {"Nguyen-2", -1, 1, [](double x) { return x * x * x * x + x * x * x + x * x + x; }},
      {"Nguyen-3", -1, 1, [](double x) { return std::pow(x, 5) + std::pow(x, 4) + x * x * x + x * x + x; }},
      {"Nguyen-4", -1, 1,
       [](double x) { return std::pow(x, 6) + std::pow(x, 5) + std::pow(x, 4) + x * x * x + x * x + x; }},
      {"Nguyen-5", -1, 1, [](double x) { return std::sin(x * x) * std::cos(x) - 1.0; }},
      {"Nguyen-6", -1, 1, [](double x) { return std::sin(x) + std::sin(x + x * x); }},
      {"Nguyen-7", 0, 2, [](double x) { return std::log(x + 1.0) + std::log(x * x + 1.0); }},
      {"Nguyen-8", 0, 4, [](double x) { return std::sqrt(x); }},
  };
  return problems;
}

Dataset sample(const Problem& problem, std::size_t rows, pbrfit::RandomStream random) {
  Dataset dataset;
  dataset.inputs.resize(static_cast<Eigen::Index>(rows), 1);
  dataset.target.resize(static_cast<Eigen::Index>(rows));
  for (Eigen::Index r = 0; r < dataset.inputs.rows(); ++r) {
    dataset.inputs(r, 0) = problem.lower + (problem.upper - problem.lower) * random.uniform();
    dataset.target[r] = problem.f(dataset.inputs(r, 0));
  }
  return dataset;
}

constexpr std::size_t island_count = 4;
constexpr std::size_t generations_per_epoch = 10;
constexpr std::size_t emigrant_count = 1;

EvolveOptions nguyen_options() {
  EvolveOptions options;
  options.shape.operators = koza_operators();
  options.shape.input_count = 1;
  options.fitness.precision = Precision::float64;  // exact recovery is judged at 1e-9
  options.target_error = 1e-12;
  return options;
}

struct Outcome {
  bool recovered = false;
  double seconds = 0.0;
  std::size_t evaluations = 0;
  std::string expression;
};

// The first archived program with a training error below the target that is also exact on fresh points.
bool find_exact(const std::vector<ArchiveEntry>& archive, BatchInterpreter<double>& fresh, std::string& expression) {
  for (const ArchiveEntry& entry : archive) {
    if (entry.fitness.error > 1e-12 || fresh.error(entry.program) >= 1e-9) continue;
    expression = print_expression(entry.program, {{"x"}, {}});
    return true;
  }
  return false;
}

Outcome run(const Problem& problem, std::uint64_t seed, std::size_t budget) {
  const auto start = std::chrono::steady_clock::now();
  const Dataset training = sample(problem, 20, pbrfit::RandomStream(seed, 1000));
  BatchInterpreter<double> fresh(sample(problem, 10'000, pbrfit::RandomStream(seed, 2000)));
  const EvolveOptions options = nguyen_options();
  std::vector<Population> islands;
  for (std::size_t i = 0; i < island_count; ++i)
    islands.push_back(random_population(options, pbrfit::RandomStream(seed, i, 0)));
  std::vector<std::vector<Individual>> inbox(island_count);
  Outcome outcome;
  for (std::uint64_t epoch = 0; outcome.evaluations < budget && !outcome.recovered; ++epoch) {
    std::vector<std::vector<Individual>> outbox(island_count);
    for (std::size_t i = 0; i < island_count && !outcome.recovered; ++i) {
      const pbrfit::RandomStream random(seed, i, epoch + 1);
      EvolveResult result = evolve(islands[i], inbox[i], generations_per_epoch, options, training, random);
      outcome.evaluations += result.stats.evaluations;
      islands[i] = std::move(result.population);
      outbox[(i + 1) % island_count] = pick_emigrants(islands[i], emigrant_count, options);
      if (result.stats.reached_target)
        outcome.recovered = find_exact(result.archive_additions, fresh, outcome.expression);
    }
    inbox = std::move(outbox);
  }
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return outcome;
}

}  // namespace

int main(int argc, char** argv) {
  const int seeds = argc > 1 ? std::atoi(argv[1]) : 10;
  const std::size_t budget = static_cast<std::size_t>((argc > 2 ? std::atof(argv[2]) : 40.0) * 1e6);
  const int first = argc > 3 ? std::atoi(argv[3]) : 1;
  const int last = argc > 4 ? std::atoi(argv[4]) : 8;
  const EvolveOptions options = nguyen_options();
  std::printf("%zu islands x %zu, ring migration of %zu every %zu generations, budget %zu evaluations per run\n",
              island_count, options.population_size, emigrant_count, generations_per_epoch, budget);
  std::printf(
      "| problem | recovered | mean s/run | max s/run | mean evaluations | example |\n|---|---|---|---|---|---|\n");
  for (int p = first; p <= last; ++p) {
    const Problem& problem = nguyen()[static_cast<std::size_t>(p - 1)];
    int recovered = 0;
    double seconds = 0.0;
    double slowest = 0.0;
    double evaluations = 0.0;
    std::string example;
    for (int seed = 0; seed < seeds; ++seed) {
      const Outcome outcome = run(problem, static_cast<std::uint64_t>(seed), budget);
      recovered += outcome.recovered;
      seconds += outcome.seconds;
      slowest = std::max(slowest, outcome.seconds);
      evaluations += static_cast<double>(outcome.evaluations);
      if (outcome.recovered && example.empty()) example = outcome.expression;
      std::fprintf(stderr, "%s seed %d: %s in %.2f s, %zu evaluations %s\n", problem.name, seed,
                   outcome.recovered ? "recovered" : "not recovered", outcome.seconds, outcome.evaluations,
                   outcome.expression.c_str());
    }
    for (char& c : example) c = c == '\n' ? ';' : c;
    std::printf("| %s | %d/%d | %.2f | %.2f | %.3g | `%s` |\n", problem.name, recovered, seeds, seconds / seeds,
                slowest, evaluations / seeds, example.c_str());
    std::fflush(stdout);
  }
  return 0;
}
