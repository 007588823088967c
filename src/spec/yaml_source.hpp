#pragma once
// A YAML text under validation: turns yaml-cpp marks (0-based) into 1-based SourcePositions and
// describes values the way messages quote them.
#include <yaml-cpp/yaml.h>

#include <string>

#include "pbrfit/core/error.hpp"

namespace pbrfit::spec {

class YamlSource {
 public:
  // Both strings must outlive the YamlSource.
  YamlSource(const std::string& text, const std::string& file) : text_(text), file_(file) {}

  const std::string& text() const { return text_; }
  const std::string& file() const { return file_; }
  SourcePosition position(const YAML::Mark& mark) const;

  // A null written as nothing at all (`key:`), rather than as ~ or null.
  bool is_blank(const YAML::Node& node) const;
  // For "got ...": 'text' for a scalar or an explicit null, "a mapping", "a list", "an empty value".
  std::string describe(const YAML::Node& value) const;
  // Where a problem with a key's value is reported: at the value, or at the key when the value is
  // blank (yaml-cpp marks a blank value at the next token, which may be lines further down).
  SourcePosition value_position(const YAML::Node& key, const YAML::Node& value) const;

 private:
  std::string null_text(const YAML::Node& node) const;  // "~", "null", ... or "" when blank
  const std::string& text_;
  const std::string& file_;
};

}  // namespace pbrfit::spec
