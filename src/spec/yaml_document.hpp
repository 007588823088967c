#pragma once
#include <yaml-cpp/yaml.h>

#include "yaml_source.hpp"

namespace pbrfit::spec {

// The top-level mapping of a job text. Throws InputError when the text is empty (nothing but
// whitespace, comments and document markers), is not valid YAML, holds more than one document, or
// its document is not a mapping.
YAML::Node load_root_mapping(const YamlSource& source);

}  // namespace pbrfit::spec
