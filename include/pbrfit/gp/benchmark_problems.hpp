#pragma once
// Standard symbolic-regression problems built into pbrfit, so searches can be tried and measured without
// data files: Nguyen-1..8 (Uy et al. 2011), one input each, sampled uniformly on their customary ranges.
//   nguyen1  x^3 + x^2 + x                 [-1, 1]     nguyen5  sin(x^2) cos(x) - 1          [-1, 1]
//   nguyen2  x^4 + x^3 + x^2 + x           [-1, 1]     nguyen6  sin(x) + sin(x + x^2)        [-1, 1]
//   nguyen3  x^5 + x^4 + x^3 + x^2 + x     [-1, 1]     nguyen7  ln(x + 1) + ln(x^2 + 1)      [0, 2]
//   nguyen4  x^6 + ... + x                 [-1, 1]     nguyen8  sqrt(x)                      [0, 4]
// Contract: sample() draws row r's input from random.derive(r), so a dataset is a pure function of
// (problem, rows, stream key); targets are exact in double.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/gp/dataset.hpp"

namespace pbrfit::gp {

struct BenchmarkProblem {
  std::string name;     // e.g. "nguyen7"
  std::string formula;  // as an expression text
  double lower = -1.0, upper = 1.0;
  double (*f)(double) = nullptr;
};

const std::vector<BenchmarkProblem>& benchmark_problems();
// nullptr for an unknown name.
const BenchmarkProblem* find_benchmark_problem(std::string_view name);
Dataset sample(const BenchmarkProblem& problem, std::size_t rows, const RandomStream& random);

}  // namespace pbrfit::gp
