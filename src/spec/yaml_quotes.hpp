#pragma once
// Quoted values must end on the line they start. yaml-cpp accepts a quote left open to the end of the
// file (taking the rest of the file as the value), which would then be reported as missing keys far
// from the mistake; pbrfit reports the open quote itself. Private to spec.
#include <yaml-cpp/yaml.h>

#include "yaml_source.hpp"

namespace pbrfit::spec {

// Throws InputError at the first quoted scalar whose closing quote is not on its line.
void reject_unclosed_quotes(const YAML::Node& node, const YamlSource& source);

}  // namespace pbrfit::spec
