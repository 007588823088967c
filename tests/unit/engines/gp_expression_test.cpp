#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "gp_test_support.hpp"
#include "pbrfit/gp/batch_interpreter.hpp"
#include "pbrfit/gp/expression_parser.hpp"
#include "pbrfit/gp/expression_printer.hpp"
#include "pbrfit/gp/live_code.hpp"
#include "pbrfit/gp/tree_walker.hpp"

using namespace pbrfit::gp;

namespace {

const ExpressionNames names{{"nv", "roughness"}, {"a", "b"}};

ParsedExpression parsed(const std::string& text, const ExpressionNames& with = names) {
  const auto result = parse_expression(text, with);
  if (const auto* error = std::get_if<ExpressionError>(&result)) {
    FAIL(text << " -> " << error->line << ":" << error->column << ": " << error->message);
  }
  return std::get<ParsedExpression>(result);
}

ExpressionError error_of(const std::string& text) {
  const auto result = parse_expression(text, names);
  REQUIRE(std::holds_alternative<ExpressionError>(result));
  return std::get<ExpressionError>(result);
}

double at(const Program& program, double nv, double roughness) {
  const double row[2] = {nv, roughness};
  return walk_tree<double>(program, std::span<const double>(row, 2));
}

}  // namespace

TEST_CASE("Expressions parse with precedence, functions, parameters and bindings", "[gp]") {
  CHECK(at(parsed("1 + 2 * nv - roughness / 4").program, 0.5, 2.0) == 1.5);
  CHECK(at(parsed("-nv * 2").program, 0.5, 0.0) == -1.0);
  CHECK(at(parsed("2 - -3 - 1").program, 0, 0) == 4.0);
  CHECK(at(parsed("fma(nv, 2, roughness) + max(nv, roughness)").program, 0.25, 3.0) == 6.5);
  CHECK(std::abs(at(parsed("pow(nv, 2) + sqrt(-4) + log2(-8)").program, -3.0, 0.0) - 14.0) < 1e-14);
  CHECK(at(parsed("  t = nv * nv ; u = t + 1\n # comment\n u * t  # trailing").program, 2.0, 0.0) == 20.0);
  CHECK(at(parsed("1.5e1 + .5 + 2.").program, 0, 0) == 17.5);
  const ParsedExpression model = parsed("a * exp2(-(7 * nv + b * roughness * roughness)) + a");
  REQUIRE(model.parameter_slots.size() == 2);
  CHECK(model.parameter_slots[0].size() == 2);  // a is used twice
  CHECK(model.parameter_slots[1].size() == 1);
  Program fitted = model.program;
  set_parameters(fitted, model.parameter_slots, std::vector<double>{0.5, 4.0});
  CHECK(std::abs(at(fitted, 0.2, 0.5) - (0.5 * std::exp2(-(1.4 + 1.0)) + 0.5)) < 1e-15);
}

TEST_CASE("Equal subexpressions become one instruction", "[gp]") {
  const Program shared = parsed("sin(nv * roughness) + sin(nv * roughness) * (nv * roughness)").program;
  CHECK(live_length(shared) == 4);          // mul, sin, mul, add
  CHECK(parsed("nv").program.length == 1);  // a bare input is an identity instruction
}

TEST_CASE("Parse errors carry the line and column of the offending token", "[gp]") {
  const auto check = [](const std::string& text, std::size_t line, std::size_t column, const std::string& words) {
    const ExpressionError error = error_of(text);
    CAPTURE(text, error.message);
    CHECK(error.line == line);
    CHECK(error.column == column);
    CHECK(error.message.find(words) != std::string::npos);
  };
  check("nv + foo", 1, 6, "unknown name 'foo'");
  check("t = nv\nt + sin(nv, 2)", 2, 5, "takes 1 argument");
  check("t = nv\n\n  t ^ 2", 3, 5, "unexpected character '^'");
  check("(nv + 1", 1, 8, "expected ')'");
  check("nv +", 1, 5, "ends early");
  check("frobnicate(nv)", 1, 1, "unknown function");
  check("sin + 1", 1, 1, "needs its arguments");
  check("nv = 1\nnv", 1, 1, "cannot be bound");
  check("t = 1\nt = 2\nt", 2, 1, "already bound");
  check("t = nv", 1, 7, "ends with a binding");
  check("", 1, 1, "no expression");
  check("nv nv", 1, 4, "expected the end");
  check("1e999", 1, 1, "out of range");
  check(std::string(300, '(') + "nv" + std::string(300, ')'), 1, 201, "nested too deeply");
  std::string long_sum = "nv";
  for (int i = 0; i < 70; ++i) long_sum += " + sin(nv * " + std::to_string(i) + ")";
  CHECK(error_of(long_sum).message.find("more than 64") != std::string::npos);
}

TEST_CASE("Parse, print, parse gives the same program and the same text", "[gp]") {
  const std::vector<std::string> texts{
      "1 + 2 * nv - roughness / 4",
      "-(nv * roughness) - -2.5 * -nv",
      "a * exp2(-(7 * nv + b * roughness * roughness))",
      "1 - a - roughness * roughness * max(a, min(roughness, 0.739 + 0.323 * nv) - 0.434)",
      "t = sin(nv) * cos(roughness)\nt * t + saturate(t) / fma(t, 0.1, 1e-07)",
      "nv - (roughness - 1) / (2 / nv)",
      "-(2)",
      "roughness",
      "0.1",
  };
  for (const std::string& text : texts) {
    const ParsedExpression first = parsed(text);
    const std::string printed = print_expression(first.program, names, first.parameter_slots);
    const ParsedExpression second = parsed(printed);
    CAPTURE(text, printed);
    CHECK(second.program == first.program);
    CHECK(second.parameter_slots == first.parameter_slots);
    CHECK(print_expression(second.program, names, second.parameter_slots) == printed);
  }
}

TEST_CASE("Random programs print to texts that compute the same values", "[gp]") {
  const ProgramShape shape = gp_test::wide_shape(2);
  const ExpressionNames inputs{{"x", "y"}, {}};
  const Dataset dataset = gp_test::sampled_dataset(50, 2, -2.0, 2.0, [](auto) { return 0.0; });
  BatchInterpreter<double> interpreter(dataset);
  std::vector<double> original(50);
  std::vector<double> reparsed(50);
  for (std::uint64_t i = 0; i < 300; ++i) {
    const Program program = gp_test::random_program(shape, 11, i);
    const std::string text = print_expression(program, inputs);
    const Program back = parsed(text, inputs).program;
    interpreter.evaluate(program, original);
    interpreter.evaluate(back, reparsed);
    CAPTURE(text);
    for (std::size_t r = 0; r < 50; ++r) {
      CHECK((original[r] == reparsed[r] || (std::isnan(original[r]) && std::isnan(reparsed[r]))));
    }
  }
}

TEST_CASE("Constants print with the fewest digits that read back exactly", "[gp]") {
  CHECK(shortest_decimal(0.1) == "0.1");
  CHECK(shortest_decimal(2.0) == "2");
  CHECK(shortest_decimal(-1e-7) == "-1e-07");
  for (double value : {0.1 + 0.2, 1.0 / 3.0, 6.02214076e23, -4.9e-324}) {
    CHECK(std::strtod(shortest_decimal(value).c_str(), nullptr) == value);
  }
}
