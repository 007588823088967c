#include "message_text.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>

namespace pbrfit::spec {

std::string format_number(double value) {
  if (value == std::trunc(value) && std::fabs(value) < 1e15) {
    return std::to_string(static_cast<std::int64_t>(value));
  }
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

std::string join(const std::vector<std::string>& items, std::string_view separator) {
  std::string out;
  for (const std::string& item : items) {
    if (!out.empty()) out += separator;
    out += item;
  }
  return out;
}

std::string type_requirement(const Field& field) {
  switch (field.type) {
    case FieldType::boolean: return "true or false";
    case FieldType::integer: return "an integer";
    case FieldType::number: return "a number";
    case FieldType::string: return "a string";
    case FieldType::choice: return "one of " + join(field.choices);
    case FieldType::integer_list: {
      std::string counts = std::to_string(field.list_min);
      if (field.list_max != field.list_min) counts += " to " + std::to_string(field.list_max);
      return "a list of " + counts + (field.list_max == 1 ? " integer" : " integers");
    }
    case FieldType::section: return "a mapping";
  }
  return "valid";
}

std::string range_requirement(const Field& field) {
  const std::string lower = field.min ? format_number(*field.min) : "";
  const std::string upper = field.max ? format_number(*field.max) : "";
  if (field.min && field.max) {
    return field.min_exclusive ? "greater than " + lower + " and at most " + upper
                               : "between " + lower + " and " + upper;
  }
  if (field.min) return (field.min_exclusive ? "greater than " : "at least ") + lower;
  if (field.max) return "at most " + upper;
  return "";
}

bool in_range(const Field& field, double value) {
  if (field.min && (field.min_exclusive ? value <= *field.min : value < *field.min)) return false;
  if (field.max && value > *field.max) return false;
  return true;
}

std::string suggestion(const std::string& word, const std::vector<std::string>& candidates) {
  const std::string closest = closest_match(word, candidates);
  return closest.empty() ? "" : "; did you mean " + quote(closest) + "?";
}

}  // namespace pbrfit::spec
