#pragma once
// Expression texts: how users state a model (the sweep job kind) and how found programs are reported.
// A text is one or more statements, separated by line breaks or ';'; all but the last bind a name
// (`t = x * x`), the last is the model. '#' starts a comment that runs to the end of the line.
//
//   expression := term { ('+' | '-') term }
//   term       := unary { ('*' | '/') unary }
//   unary      := '-' unary | primary            (a '-' directly before a number is part of the number)
//   primary    := number | name | function '(' expression { ',' expression } ')' | '(' expression ')'
//
// Names are inputs, parameters or earlier bindings; functions are the operator names of opcode.hpp
// (min, max, abs, neg, sqrt, rsqrt, exp, exp2, log, log2, pow, sin, cos, saturate, fma, add, sub, mul,
// div) with their semantics (semantics.hpp). Numbers are decimal, with an optional exponent.
//
// Contract: on success, a valid program for names.inputs.size() inputs whose equal subexpressions are
// shared (one instruction each) and whose only introns are unused bindings; every use of parameter k is a
// constant operand holding parameter_values[k] (1 when not given), listed in parameter_slots[k]. On
// failure, the first error with its 1-based line and column (in bytes) and a message; never an exception
// for any input text.
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "pbrfit/gp/program.hpp"
#include "pbrfit/gp/program_builder.hpp"

namespace pbrfit::gp {

struct ExpressionNames {
  std::vector<std::string> inputs;      // input k is data column k
  std::vector<std::string> parameters;  // fitted constants with names
};

struct ParsedExpression {
  Program program;
  std::vector<std::vector<ConstantSlot>> parameter_slots;  // per parameter, the constants that hold it
};

struct ExpressionError {
  std::size_t line = 1;
  std::size_t column = 1;
  std::string message;
};

std::variant<ParsedExpression, ExpressionError> parse_expression(std::string_view text, const ExpressionNames& names,
                                                                 std::span<const double> parameter_values = {});

// Writes values[k] into every slot of parameter k.
void set_parameters(Program& program, std::span<const std::vector<ConstantSlot>> parameter_slots,
                    std::span<const double> values);

}  // namespace pbrfit::gp
