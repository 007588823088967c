// Folding the parameter-free part of a program out into data columns (gp/fixed_part.hpp): the folded
// program computes the original at every row for any parameter values, and is shorter.
#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <vector>

#include "gp_test_support.hpp"
#include "pbrfit/gp/batch_interpreter.hpp"
#include "pbrfit/gp/expression_parser.hpp"
#include "pbrfit/gp/fixed_part.hpp"

using namespace pbrfit;
using namespace pbrfit::gp;

namespace {

const ExpressionNames names{{"x", "y"}, {"p0", "p1"}};

ParsedExpression parsed(const char* text) { return std::get<ParsedExpression>(parse_expression(text, names)); }

std::vector<double> outputs(Program program, std::span<const std::vector<ConstantSlot>> slots, const Dataset& data,
                            const std::vector<double>& parameters) {
  set_parameters(program, slots, parameters);
  BatchInterpreter<double> interpreter(data);
  std::vector<double> out(interpreter.rows());
  interpreter.evaluate(program, out);
  return out;
}

// The largest difference of the two programs' outputs, relative to the larger magnitude (at least 1).
double largest_difference(const char* text, const Dataset& data, const std::vector<double>& parameters) {
  const auto p = parsed(text);
  const auto folded = fold_fixed_part(p.program, p.parameter_slots, data);
  const auto before = outputs(p.program, p.parameter_slots, data, parameters);
  const auto after = outputs(folded.program, folded.parameter_slots, folded.dataset, parameters);
  double worst = 0.0;
  for (std::size_t r = 0; r < before.size(); ++r)
    worst = std::max(worst, std::abs(before[r] - after[r]) / std::max({1.0, std::abs(before[r]), std::abs(after[r])}));
  return worst;
}

const Dataset data = gp_test::sampled_dataset(64, 2, 0.1, 0.9, [](auto) { return 0.0; });

}  // namespace

TEST_CASE("a folded program computes the original for any parameters and reads its fixed values as columns") {
  const char* text = "p0 + p1 * (exp(-(tan(acos(x)) * tan(acos(x)))) / (x * x * y)) * min(1, 2 * x / y)";
  for (const auto& parameters : {std::vector<double>{0.0, 1.0}, {0.3, -2.5}, {17.0, 0.01}})
    CHECK(largest_difference(text, data, parameters) < 1e-12);
  const auto p = parsed(text);
  const auto folded = fold_fixed_part(p.program, p.parameter_slots, data);
  CHECK(folded.program.length < p.program.length);
  CHECK(folded.dataset.input_count() > data.input_count());
  CHECK(folded.dataset.rows() == data.rows());
  CHECK(folded.dataset.target.isApprox(data.target));
  REQUIRE(folded.parameter_slots.size() == p.parameter_slots.size());
  CHECK_FALSE(folded.parameter_slots[0].empty());
  CHECK_FALSE(folded.parameter_slots[1].empty());
}

TEST_CASE("a parameter used twice stays one parameter, and an unused one stays unused") {
  const char* text = "p0 * sin(x) + p0 * cos(y)";
  CHECK(largest_difference(text, data, {1.7, 0.0}) < 1e-12);
  const auto p = parsed(text);
  const auto folded = fold_fixed_part(p.program, p.parameter_slots, data);
  CHECK(folded.parameter_slots[0].size() == p.parameter_slots[0].size());
  CHECK(folded.parameter_slots[1].empty());
}

TEST_CASE("a program that reads no parameter folds to its output column") {
  const char* text = "sqrt(x * y) + exp(x)";
  const auto p = parsed(text);
  const auto folded = fold_fixed_part(p.program, p.parameter_slots, data);
  CHECK(folded.program.length == 1);
  CHECK(largest_difference(text, data, {0.0, 0.0}) < 1e-12);
}

TEST_CASE("a program without a fixed part is left as it is") {
  const char* text = "p0 * p1 + p0";
  const auto p = parsed(text);
  const auto folded = fold_fixed_part(p.program, p.parameter_slots, data);
  CHECK(folded.program.length == p.program.length);
  CHECK(folded.dataset.input_count() == data.input_count());
  CHECK(largest_difference(text, data, {2.0, 3.0}) < 1e-12);
}

TEST_CASE("a fixed value that is not finite at some row stays computed by the program") {
  // 1 / (x - x) is infinite at every row; min(p0, 1 / (x - x)) is p0 nonetheless.
  const char* text = "min(p0, 1 / (x - x)) + p1 * sqrt(y)";
  const auto p = parsed(text);
  const auto folded = fold_fixed_part(p.program, p.parameter_slots, data);
  CHECK(folded.dataset.inputs.allFinite());
  const auto after = outputs(folded.program, folded.parameter_slots, folded.dataset, {0.5, 2.0});
  for (Eigen::Index r = 0; r < data.inputs.rows(); ++r) CHECK(after[std::size_t(r)] == 0.5 + 2.0 * std::sqrt(data.inputs(r, 1)));
}
