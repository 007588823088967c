#include "yaml_source.hpp"

#include <array>
#include <string_view>

#include "message_text.hpp"

namespace pbrfit::spec {

SourcePosition YamlSource::position(const YAML::Mark& mark) const {
  if (mark.is_null() || mark.line < 0 || mark.column < 0) return SourcePosition{file_, 0, 0};
  return SourcePosition{file_, mark.line + 1, mark.column + 1};
}

std::string YamlSource::null_text(const YAML::Node& node) const {
  const int at = node.Mark().pos;
  if (at < 0 || static_cast<std::size_t>(at) >= text_.size()) return "";
  const std::string_view rest = std::string_view(text_).substr(static_cast<std::size_t>(at));
  // The plain scalars YAML reads as null; a blank value is marked at whatever token follows it.
  constexpr std::array<std::string_view, 4> spellings = {"~", "null", "Null", "NULL"};
  for (std::string_view spelling : spellings) {
    if (rest.starts_with(spelling)) return std::string(spelling);
  }
  return "";
}

bool YamlSource::is_blank(const YAML::Node& node) const {
  return node.IsNull() && null_text(node).empty();
}

std::string YamlSource::describe(const YAML::Node& value) const {
  if (value.IsMap()) return "a mapping";
  if (value.IsSequence()) return "a list";
  if (value.IsScalar()) return quote(value.Scalar());
  const std::string written = null_text(value);
  return written.empty() ? "an empty value" : quote(written);
}

SourcePosition YamlSource::value_position(const YAML::Node& key, const YAML::Node& value) const {
  return position(is_blank(value) ? key.Mark() : value.Mark());
}

}  // namespace pbrfit::spec
