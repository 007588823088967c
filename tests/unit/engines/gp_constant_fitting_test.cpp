#include <catch2/catch_test_macros.hpp>
#include <cmath>

#include "gp_test_support.hpp"
#include "pbrfit/gp/constant_fitting.hpp"
#include "pbrfit/gp/expression_parser.hpp"

using namespace pbrfit::gp;

namespace {

Program parsed(const char* text) {
  const auto result = parse_expression(text, {{"x"}, {}});
  REQUIRE(std::holds_alternative<ParsedExpression>(result));
  return std::get<ParsedExpression>(result).program;
}

}  // namespace

TEST_CASE("Constant fitting recovers known constants and counts every evaluation", "[gp]") {
  const Dataset dataset = gp_test::sampled_dataset(
      64, 1, -1.0, 2.0, [](auto x) { return 2.5 * x[0] * x[0] + 0.7 * std::exp(-1.3 * x[0]); });
  const Program start = parsed("1 * x * x + 1 * exp(-1 * x)");
  REQUIRE(live_constant_slots(start).size() == 3);
  FitnessOptions options;
  options.precision = Precision::float64;
  FitnessEvaluator evaluator(dataset, options);
  const double start_error = evaluator.error(start);
  ConstantFitOptions fit;
  fit.max_evaluations = 2000;
  const ConstantFitResult result = fit_constants(start, start_error, evaluator, fit);
  CHECK(result.error < 1e-7);
  CHECK(result.evaluations <= 2000);
  CHECK(evaluator.evaluations() == result.evaluations + 1);
  const auto slots = live_constant_slots(result.program);
  auto constant = [&](std::size_t k) { return result.program.code[slots[k].instruction].constants[slots[k].operand]; };
  CHECK(std::abs(constant(0) - 2.5) < 1e-5);
  CHECK(std::abs(constant(1) + 1.3) < 1e-5);  // -1 * x comes before the exp's factor
  CHECK(std::abs(constant(2) - 0.7) < 1e-5);
}

TEST_CASE("Constant fitting never makes a program worse and leaves constant-free programs alone", "[gp]") {
  const Dataset dataset = gp_test::sampled_dataset(32, 1, 0.0, 1.0, [](auto x) { return x[0]; });
  FitnessEvaluator evaluator(dataset, {});
  const Program exact = parsed("x * 1");
  const ConstantFitResult kept = fit_constants(exact, evaluator.error(exact), evaluator, {});
  CHECK(kept.error <= evaluator.error(exact));
  const Program free = parsed("x * x");
  const ConstantFitResult untouched = fit_constants(free, 0.5, evaluator, {});
  CHECK(untouched.evaluations == 0);
  CHECK(untouched.program == free);
}
