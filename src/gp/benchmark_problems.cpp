#include "pbrfit/gp/benchmark_problems.hpp"

#include <cmath>

namespace pbrfit::gp {
namespace {

double polynomial(double x, int degree) {
  double sum = 0.0, power = 1.0;
  for (int k = 1; k <= degree; ++k) sum += power *= x;
  return sum;
}

}  // namespace

const std::vector<BenchmarkProblem>& benchmark_problems() {
  static const std::vector<BenchmarkProblem> problems = {
      {"nguyen1", "x*x*x + x*x + x", -1, 1, [](double x) { return polynomial(x, 3); }},
      {"nguyen2", "x*x*x*x + x*x*x + x*x + x", -1, 1, [](double x) { return polynomial(x, 4); }},
      {"nguyen3", "pow(x, 5) + pow(x, 4) + x*x*x + x*x + x", -1, 1, [](double x) { return polynomial(x, 5); }},
      {"nguyen4", "pow(x, 6) + pow(x, 5) + pow(x, 4) + x*x*x + x*x + x", -1, 1, [](double x) { return polynomial(x, 6); }},
      {"nguyen5", "sin(x*x) * cos(x) - 1", -1, 1, [](double x) { return std::sin(x * x) * std::cos(x) - 1.0; }},
      {"nguyen6", "sin(x) + sin(x + x*x)", -1, 1, [](double x) { return std::sin(x) + std::sin(x + x * x); }},
      {"nguyen7", "log(x + 1) + log(x*x + 1)", 0, 2, [](double x) { return std::log(x + 1.0) + std::log(x * x + 1.0); }},
      {"nguyen8", "sqrt(x)", 0, 4, [](double x) { return std::sqrt(x); }},
  };
  return problems;
}

const BenchmarkProblem* find_benchmark_problem(std::string_view name) {
  for (const auto& p : benchmark_problems())
    if (p.name == name) return &p;
  return nullptr;
}

Dataset sample(const BenchmarkProblem& problem, std::size_t rows, const RandomStream& random) {
  Dataset dataset;
  dataset.inputs.resize(Eigen::Index(rows), 1);
  dataset.target.resize(Eigen::Index(rows));
  for (std::size_t r = 0; r < rows; ++r) {
    RandomStream row = random.derive(r);
    const double x = problem.lower + (problem.upper - problem.lower) * row.uniform();
    dataset.inputs(Eigen::Index(r), 0) = x;
    dataset.target[Eigen::Index(r)] = problem.f(x);
  }
  return dataset;
}

}  // namespace pbrfit::gp
