#include "expression_lexer.hpp"

#include <charconv>
#include <cmath>
#include <string>
#include <system_error>

namespace pbrfit::gp::detail {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_name_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_name_char(char c) { return is_name_start(c) || is_digit(c); }

TokenKind punctuation(char c) {
  switch (c) {
    case '+':
      return TokenKind::plus;
    case '-':
      return TokenKind::minus;
    case '*':
      return TokenKind::times;
    case '/':
      return TokenKind::divide;
    case '(':
      return TokenKind::open;
    case ')':
      return TokenKind::close;
    case ',':
      return TokenKind::comma;
    case '=':
      return TokenKind::assign;
    case ';':
    case '\n':
      return TokenKind::separator;
    default:
      return TokenKind::end;
  }
}

class Lexer {
 public:
  explicit Lexer(std::string_view text) : text_(text) {}

  std::variant<std::vector<Token>, ExpressionError> run() {
    std::vector<Token> tokens;
    for (;;) {
      skip_blanks();
      Token token{TokenKind::end, {}, 0.0, line_, at_ - line_start_ + 1};
      if (at_ >= text_.size()) {
        tokens.push_back(token);
        return tokens;
      }
      const char c = text_[at_];
      if (is_digit(c) || (c == '.' && at_ + 1 < text_.size() && is_digit(text_[at_ + 1]))) {
        if (!number(token))
          return ExpressionError{token.line, token.column, "number out of range: " + std::string(token.text)};
      } else if (is_name_start(c)) {
        token.kind = TokenKind::name;
        token.text = take_while(is_name_char);
      } else if (punctuation(c) != TokenKind::end) {
        token.kind = punctuation(c);
        token.text = text_.substr(at_++, 1);
        if (c == '\n') {
          ++line_;
          line_start_ = at_;
        }
      } else {
        return ExpressionError{token.line, token.column, "unexpected character '" + std::string(1, c) + "'"};
      }
      tokens.push_back(token);
    }
  }

 private:
  void skip_blanks() {
    while (at_ < text_.size()) {
      const char c = text_[at_];
      if (c == '#') {
        while (at_ < text_.size() && text_[at_] != '\n') ++at_;
      } else if (c == ' ' || c == '\t' || c == '\r') {
        ++at_;
      } else {
        return;
      }
    }
  }

  template <class Predicate>
  std::string_view take_while(Predicate predicate) {
    const std::size_t start = at_;
    while (at_ < text_.size() && predicate(text_[at_])) ++at_;
    return text_.substr(start, at_ - start);
  }

  // digits [. digits] [e [+-] digits]
  bool number(Token& token) {
    const std::size_t start = at_;
    take_while(is_digit);
    if (at_ < text_.size() && text_[at_] == '.') {
      ++at_;
      take_while(is_digit);
    }
    const bool has_exponent = at_ < text_.size() && (text_[at_] == 'e' || text_[at_] == 'E');
    const std::size_t sign = at_ + 1 < text_.size() && (text_[at_ + 1] == '+' || text_[at_ + 1] == '-') ? 1 : 0;
    if (has_exponent && at_ + 1 + sign < text_.size() && is_digit(text_[at_ + 1 + sign])) {
      at_ += 1 + sign;
      take_while(is_digit);
    }
    token.kind = TokenKind::number;
    token.text = text_.substr(start, at_ - start);
    const auto [end, status] = std::from_chars(token.text.data(), token.text.data() + token.text.size(), token.value);
    return status == std::errc() && end == token.text.data() + token.text.size() && std::isfinite(token.value);
  }

  std::string_view text_;
  std::size_t at_ = 0;
  std::size_t line_ = 1;
  std::size_t line_start_ = 0;
};

}  // namespace

std::variant<std::vector<Token>, ExpressionError> tokenize(std::string_view text) { return Lexer(text).run(); }

}  // namespace pbrfit::gp::detail
