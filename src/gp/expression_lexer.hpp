#pragma once
// Splits an expression text into tokens with their 1-based line and column. Comments ('#' to the end of
// the line), spaces, tabs and carriage returns are skipped; a line break and ';' both end a statement.
#include <cstddef>
#include <string_view>
#include <variant>
#include <vector>

#include "pbrfit/gp/expression_parser.hpp"

namespace pbrfit::gp::detail {

enum class TokenKind { number, name, plus, minus, times, divide, open, close, comma, assign, separator, end };

struct Token {
  TokenKind kind = TokenKind::end;
  std::string_view text;
  double value = 0.0;  // numbers
  std::size_t line = 1;
  std::size_t column = 1;
};

// The tokens, ending with one `end` token, or the first lexical error.
std::variant<std::vector<Token>, ExpressionError> tokenize(std::string_view text);

}  // namespace pbrfit::gp::detail
