#pragma once
// Shorthands for the result layout of the brdf jobs. Private to them.
#include <map>
#include <string>
#include <vector>

#include "pbrfit/store/result_layout.hpp"

namespace pbrfit::jobs::brdf {

// A growing table of records.
inline store::Table records(const char* name, const char* label, const char* description,
                            std::vector<store::Field> fields, std::map<std::string, std::string> attributes = {}) {
  store::Table t{name, {label}, description, store::ValueType::f64, std::move(fields), true};
  t.attributes = std::move(attributes);
  return t;
}

// "a, b, c".
inline std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

}  // namespace pbrfit::jobs::brdf
