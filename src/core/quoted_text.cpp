#include "pbrfit/core/quoted_text.hpp"

#include <algorithm>
#include <cstdio>

namespace pbrfit {

namespace {

constexpr std::size_t max_quoted_length = 60;

bool is_control(char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; }

void append_escaped(std::string& out, char c) {
  switch (c) {
    case '\n': out += "\\n"; return;
    case '\r': out += "\\r"; return;
    case '\t': out += "\\t"; return;
    default: break;
  }
  if (!is_control(c)) {
    out += c;
    return;
  }
  char escaped[8];
  std::snprintf(escaped, sizeof escaped, "\\x%02x", static_cast<unsigned char>(c));
  out += escaped;
}

}  // namespace

std::string shortened(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const bool starts_character = (static_cast<unsigned char>(text[i]) & 0xC0) != 0x80;  // UTF-8
    if (i >= max_quoted_length && starts_character) {
      out += "...";
      break;
    }
    append_escaped(out, text[i]);
  }
  return out;
}

std::string quote(std::string_view text) { return "'" + shortened(text) + "'"; }

std::string one_line(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) append_escaped(out, c);
  return out;
}

bool has_control_character(std::string_view text) { return std::any_of(text.begin(), text.end(), is_control); }

}  // namespace pbrfit
