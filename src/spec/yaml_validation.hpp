#pragma once
// Checks YAML mappings against Schemas and turns them into Sections.
//
// A mapping's path names it in messages: "" for the top level (shown as 'job'), "checkpoint",
// "lut.n_dot_v". Keys are checked in document order, then missing required keys, so the error reported
// is the first one in the file (missing keys last).
#include <yaml-cpp/yaml.h>

#include <string>

#include "pbrfit/spec/schema.hpp"
#include "yaml_source.hpp"

namespace pbrfit::spec {

// Throws at the second occurrence of a key repeated within one mapping, anywhere in node; also at an
// alias of a mapping or list that contains it, and when aliases expand the document beyond its size
// in characters. Afterwards the document is known to be finite, so any walk over it terminates.
void reject_duplicate_keys(const YAML::Node& node, const std::string& path, const YamlSource& source);

// Requires unique keys (see reject_duplicate_keys).
Section validate_mapping(const YAML::Node& mapping, const Schema& schema, const std::string& path,
                         const YamlSource& source);

// The checked value of a field that is not a section, written as `key: value`.
Section::Entry validate_value(const Field& field, const YAML::Node& key, const YAML::Node& value,
                              const YamlSource& source);

// The key's name; throws when the key is not a scalar.
std::string key_name(const YAML::Node& key, const std::string& path, const YamlSource& source);

// "job" for the top level, else the path itself.
std::string display_path(const std::string& path);

}  // namespace pbrfit::spec
