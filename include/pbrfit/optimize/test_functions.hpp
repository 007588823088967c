#pragma once
// Standard test problems for the optimizers, in any dimension >= 1 (Rosenbrock >= 2), with their
// customary search domains and known global minima. Each minimum is 0, attained where every coordinate
// equals minimizer_coordinate, and evaluates to exactly 0 there.
//   sphere      sum x_i^2                                          minimizer 0
//   rosenbrock  sum 100 (x_{i+1} - x_i^2)^2 + (1 - x_i)^2           minimizer 1 (narrow curved valley)
//   rastrigin   10 n + sum x_i^2 - 10 cos(2 pi x_i)                 minimizer 0 (regular grid of local minima)
//   ackley      20 (1 - exp(-0.2 rms(x))) + e - exp(mean cos(2 pi x_i))   minimizer 0 (nearly flat outside)
#include <span>

namespace pbrfit::optimize {

double sphere(std::span<const double> x);
double rosenbrock(std::span<const double> x);
double rastrigin(std::span<const double> x);
double ackley(std::span<const double> x);

struct TestFunction {
  const char* name;
  double (*evaluate)(std::span<const double>);
  double lower;  // the customary domain [lower, upper] in every coordinate
  double upper;
  double minimizer_coordinate;
  double minimum;
};

inline constexpr TestFunction sphere_problem{"Sphere", sphere, -5.12, 5.12, 0.0, 0.0};
inline constexpr TestFunction rosenbrock_problem{"Rosenbrock", rosenbrock, -5.0, 10.0, 1.0, 0.0};
inline constexpr TestFunction rastrigin_problem{"Rastrigin", rastrigin, -5.12, 5.12, 0.0, 0.0};
inline constexpr TestFunction ackley_problem{"Ackley", ackley, -32.768, 32.768, 0.0, 0.0};

}  // namespace pbrfit::optimize
