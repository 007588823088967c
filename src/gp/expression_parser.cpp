#include "pbrfit/gp/expression_parser.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>

#include "expression_lexer.hpp"

namespace pbrfit::gp {
namespace {

using detail::Token;
using detail::TokenKind;

constexpr std::size_t max_nesting = 200;

struct Failure {
  ExpressionError error;
};

[[noreturn]] void fail(const Token& at, std::string message) {
  throw Failure{{at.line, at.column, std::move(message)}};
}

std::string quoted(std::string_view text) {
  std::string result(1, '\'');
  result.append(text);
  result.push_back('\'');
  return result;
}

class Parser {
 public:
  Parser(std::vector<Token> tokens, const ExpressionNames& names, std::span<const double> values)
      : tokens_(std::move(tokens)), names_(names), values_(values), builder_(true) {}

  ParsedExpression parse();

 private:
  const Token& peek(std::size_t ahead = 0) const { return tokens_[std::min(at_ + ahead, tokens_.size() - 1)]; }
  const Token& next() { return tokens_[at_ < tokens_.size() - 1 ? at_++ : at_]; }
  bool accept(TokenKind kind);
  void expect(TokenKind kind, const char* what);
  void skip_separators();

  void binding();
  Argument expression();
  Argument term();
  Argument unary();
  Argument primary();
  Argument call(const Token& function);
  Argument name(const Token& token);
  Argument apply(const Token& at, Opcode op, const std::vector<Argument>& arguments);

  std::vector<Token> tokens_;
  const ExpressionNames& names_;
  std::span<const double> values_;
  ProgramBuilder builder_;
  std::map<std::string, Argument, std::less<>> bindings_;
  std::size_t at_ = 0;
  std::size_t depth_ = 0;
};

bool Parser::accept(TokenKind kind) {
  if (peek().kind != kind) return false;
  next();
  return true;
}

void Parser::expect(TokenKind kind, const char* what) {
  if (!accept(kind)) fail(peek(), std::string("expected ") + what);
}

void Parser::skip_separators() {
  while (accept(TokenKind::separator)) {
  }
}

ParsedExpression Parser::parse() {
  skip_separators();
  if (peek().kind == TokenKind::end) fail(peek(), "the text has no expression");
  while (peek().kind == TokenKind::name && peek(1).kind == TokenKind::assign) {
    binding();
    if (peek().kind != TokenKind::end) expect(TokenKind::separator, "a line break or ';' after a binding");
    skip_separators();
    if (peek().kind == TokenKind::end)
      fail(peek(), "the text ends with a binding; the last statement must be the model");
  }
  const Argument model = expression();
  skip_separators();
  if (peek().kind != TokenKind::end) {
    fail(peek(), peek().kind == TokenKind::assign ? "a binding needs a name on its left"
                                                  : "expected the end of the text after the model expression");
  }
  ParsedExpression parsed;
  parsed.program = builder_.finish(model);
  for (std::size_t k = 0; k < names_.parameters.size(); ++k) {
    parsed.parameter_slots.push_back(builder_.slots_tagged(static_cast<std::int64_t>(k)));
  }
  return parsed;
}

void Parser::binding() {
  const Token& target = next();
  const auto& inputs = names_.inputs;
  const auto& parameters = names_.parameters;
  if (std::find(inputs.begin(), inputs.end(), target.text) != inputs.end() ||
      std::find(parameters.begin(), parameters.end(), target.text) != parameters.end()) {
    fail(target, quoted(target.text) + " is an input or parameter and cannot be bound");
  }
  if (bindings_.contains(target.text)) fail(target, quoted(target.text) + " is already bound");
  next();  // '='
  bindings_.emplace(std::string(target.text), expression());
}

Argument Parser::expression() {
  if (++depth_ > max_nesting) fail(peek(), "the expression is nested too deeply");
  Argument left = term();
  while (peek().kind == TokenKind::plus || peek().kind == TokenKind::minus) {
    const Token& op = next();
    const Argument right = term();
    left = apply(op, op.kind == TokenKind::plus ? Opcode::add : Opcode::sub, {left, right});
  }
  --depth_;
  return left;
}

Argument Parser::term() {
  Argument left = unary();
  while (peek().kind == TokenKind::times || peek().kind == TokenKind::divide) {
    const Token& op = next();
    const Argument right = unary();
    left = apply(op, op.kind == TokenKind::times ? Opcode::mul : Opcode::div, {left, right});
  }
  return left;
}

Argument Parser::unary() {
  if (peek().kind != TokenKind::minus) return primary();
  const Token& minus = next();
  if (peek().kind == TokenKind::number) return constant_argument(-next().value);
  if (++depth_ > max_nesting) fail(minus, "the expression is nested too deeply");
  const Argument operand = unary();
  --depth_;
  return apply(minus, Opcode::neg, {operand});
}

Argument Parser::primary() {
  const Token& token = next();
  switch (token.kind) {
    case TokenKind::number:
      return constant_argument(token.value);
    case TokenKind::name:
      return peek().kind == TokenKind::open ? call(token) : name(token);
    case TokenKind::open: {
      const Argument inner = expression();
      expect(TokenKind::close, "')'");
      return inner;
    }
    case TokenKind::end:
      fail(token, "the expression ends early");
    default:
      fail(token, "unexpected " + quoted(token.kind == TokenKind::separator ? "line break or ;" : token.text));
  }
}

Argument Parser::call(const Token& function) {
  const auto op = opcode_named(function.text);
  if (!op || *op == Opcode::identity) fail(function, "unknown function " + quoted(function.text));
  next();  // '('
  std::vector<Argument> arguments{expression()};
  while (accept(TokenKind::comma)) arguments.push_back(expression());
  expect(TokenKind::close, "')' or ','");
  if (static_cast<int>(arguments.size()) != arity(*op)) {
    fail(function, "function " + quoted(function.text) + " takes " + std::to_string(arity(*op)) + " argument(s), got " +
                       std::to_string(arguments.size()));
  }
  return apply(function, *op, arguments);
}

Argument Parser::name(const Token& token) {
  if (const auto bound = bindings_.find(token.text); bound != bindings_.end()) return bound->second;
  const auto& inputs = names_.inputs;
  if (const auto input = std::find(inputs.begin(), inputs.end(), token.text); input != inputs.end()) {
    return input_argument(static_cast<std::size_t>(input - inputs.begin()));
  }
  const auto& parameters = names_.parameters;
  if (const auto p = std::find(parameters.begin(), parameters.end(), token.text); p != parameters.end()) {
    const auto k = static_cast<std::size_t>(p - parameters.begin());
    return constant_argument(k < values_.size() ? values_[k] : 1.0, static_cast<std::int64_t>(k));
  }
  if (opcode_named(token.text)) fail(token, "function " + quoted(token.text) + " needs its arguments in parentheses");
  fail(token, "unknown name " + quoted(token.text));
}

Argument Parser::apply(const Token& at, Opcode op, const std::vector<Argument>& arguments) {
  try {
    return builder_.append(op, arguments.data(), arguments.size());
  } catch (const std::length_error&) {
    fail(at, "the model needs more than " + std::to_string(max_program_length) + " operations");
  } catch (const std::invalid_argument& error) {
    fail(at, error.what());
  }
}

std::optional<ExpressionError> check_names(const ExpressionNames& names, std::span<const double> values) {
  std::vector<std::string> all = names.inputs;
  all.insert(all.end(), names.parameters.begin(), names.parameters.end());
  std::sort(all.begin(), all.end());
  if (std::adjacent_find(all.begin(), all.end()) != all.end()) return ExpressionError{1, 1, "a name is given twice"};
  if (names.inputs.size() > 65535) return ExpressionError{1, 1, "too many inputs"};
  if (std::any_of(values.begin(), values.end(), [](double v) { return !std::isfinite(v); })) {
    return ExpressionError{1, 1, "a parameter value is not finite"};
  }
  return std::nullopt;
}

}  // namespace

std::variant<ParsedExpression, ExpressionError> parse_expression(std::string_view text, const ExpressionNames& names,
                                                                 std::span<const double> parameter_values) {
  if (auto problem = check_names(names, parameter_values)) return *problem;
  auto tokens = detail::tokenize(text);
  if (auto* error = std::get_if<ExpressionError>(&tokens)) return *error;
  try {
    return Parser(std::move(std::get<std::vector<Token>>(tokens)), names, parameter_values).parse();
  } catch (const Failure& failure) {
    return failure.error;
  }
}

void set_parameters(Program& program, std::span<const std::vector<ConstantSlot>> parameter_slots,
                    std::span<const double> values) {
  for (std::size_t k = 0; k < parameter_slots.size() && k < values.size(); ++k) {
    for (const ConstantSlot& slot : parameter_slots[k])
      program.code[slot.instruction].constants[slot.operand] = values[k];
  }
}

}  // namespace pbrfit::gp
