// Fitting one sweep cell: warm starts that fit well skip the global search, poor ones trigger it.
#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <vector>

#include "pbrfit/optimize/test_functions.hpp"
#include "pbrfit/sweep/cell_fit.hpp"

using namespace pbrfit;
using namespace pbrfit::sweep;

namespace {

// Rastrigin shifted to a minimum at `centre` in every coordinate, over [-5, 5]^n.
CellProblem shifted_rastrigin(std::size_t n, double centre) {
  CellProblem problem;
  for (std::size_t d = 0; d < n; ++d)
    problem.parameters.add({"x" + std::to_string(d), -5.0, 5.0, optimize::Transform::linear});
  problem.error = [centre](std::span<const double> x) {
    std::vector<double> shifted(x.begin(), x.end());
    for (double& v : shifted) v -= centre;
    return optimize::rastrigin(shifted);
  };
  return problem;
}

CellFitOptions options_with(GlobalPolicy policy) {
  CellFitOptions options;
  options.policy = policy;
  options.global.max_evaluations = 20'000;
  options.poor_absolute = 1e-8;
  return options;
}

}  // namespace

TEST_CASE("a warm start near the minimum is polished and accepted without a global search") {
  const auto problem = shifted_rastrigin(3, 0.5);
  const std::vector<WarmStart> near = {{{0.52, 0.48, 0.51}, 1e-9}};
  RandomStream random(1, 0);
  const auto fit = fit_cell(problem, near, options_with(GlobalPolicy::when_poor), random);
  CHECK(fit.error < 1e-8);
  CHECK_FALSE(fit.global_ran);
  CHECK(fit.winner == Winner::warm_start);
  CHECK(fit.evaluations <= 400);
}

TEST_CASE("a warm start in the wrong basin fits poorly, so the global search runs and finds the minimum") {
  const auto problem = shifted_rastrigin(3, 0.5);
  const std::vector<WarmStart> far = {{{-2.5, 3.5, 1.5}, 1e-9}};
  RandomStream random(2, 0);
  const auto fit = fit_cell(problem, far, options_with(GlobalPolicy::when_poor), random);
  CHECK(fit.global_ran);
  CHECK(fit.error < 1e-6);
  CHECK(fit.winner == Winner::global);
  RandomStream again(2, 0);
  const auto repeat = fit_cell(problem, far, options_with(GlobalPolicy::when_poor), again);
  CHECK(repeat.parameters == fit.parameters);
  CHECK(repeat.evaluations == fit.evaluations);
}

TEST_CASE("policy never keeps the polished warm start; policy always searches globally anyway") {
  const auto problem = shifted_rastrigin(2, 0.5);
  const std::vector<WarmStart> far = {{{-2.5, 3.5}, 1e-9}};
  RandomStream a(3, 0), b(3, 0);
  auto local_only = options_with(GlobalPolicy::never);
  local_only.warm_search.initial_step = 0.01;  // a small simplex without restarts stays in its basin
  local_only.warm_search.max_restarts = 0;
  const auto never = fit_cell(problem, far, local_only, a);
  CHECK_FALSE(never.global_ran);
  CHECK(never.evaluations <= local_only.warm_evaluations);
  CHECK(never.error > 1.0);  // stuck in its local minimum
  const std::vector<WarmStart> near = {{{0.5, 0.5}, 1e-9}};
  const auto always = fit_cell(problem, near, options_with(GlobalPolicy::always), b);
  CHECK(always.global_ran);
  CHECK(always.error < 1e-8);
}

TEST_CASE("without warm starts a cell starts from the default start or searches globally") {
  auto problem = shifted_rastrigin(2, 0.5);
  problem.default_start = {0.45, 0.55};
  RandomStream a(4, 0), b(4, 0);
  const auto from_default = fit_cell(problem, {}, options_with(GlobalPolicy::never), a);
  CHECK(from_default.winner == Winner::default_start);
  CHECK(from_default.error < 1e-8);
  problem.default_start.clear();
  const auto cold = fit_cell(problem, {}, options_with(GlobalPolicy::when_poor), b);
  CHECK(cold.global_ran);
  CHECK(cold.error < 1e-6);
}
