#include "pbrfit/optimize/test_functions.hpp"

#include <cmath>
#include <numbers>

namespace pbrfit::optimize {

double sphere(std::span<const double> x) {
  double sum = 0.0;
  for (double coordinate : x) sum += coordinate * coordinate;
  return sum;
}

double rosenbrock(std::span<const double> x) {
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < x.size(); ++i) {
    const double valley = x[i + 1] - x[i] * x[i];
    const double offset = 1.0 - x[i];
    sum += 100.0 * valley * valley + offset * offset;
  }
  return sum;
}

double rastrigin(std::span<const double> x) {
  double sum = 0.0;
  for (double coordinate : x) {
    sum += coordinate * coordinate + 10.0 * (1.0 - std::cos(2.0 * std::numbers::pi * coordinate));
  }
  return sum;
}

double ackley(std::span<const double> x) {
  double squares = 0.0;
  double cosines = 0.0;
  for (double coordinate : x) {
    squares += coordinate * coordinate;
    cosines += std::cos(2.0 * std::numbers::pi * coordinate);
  }
  const double count = static_cast<double>(x.size());
  const double envelope = 20.0 * (1.0 - std::exp(-0.2 * std::sqrt(squares / count)));
  return envelope + (std::numbers::e - std::exp(cosines / count));
}

}  // namespace pbrfit::optimize
