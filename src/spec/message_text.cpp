#include "message_text.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>

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

std::string choice_list(const std::vector<std::string>& choices) {
  constexpr std::size_t spelled_out = 30;  // a longer list (100 MERL names) would drown the one-line error
  if (choices.size() <= spelled_out) return "one of " + join(choices);
  return "one of " + std::to_string(choices.size()) + " names (" + choices.front() + ", " + choices[1] + ", ..., " +
         choices.back() + ")";
}

namespace {

// "a list of 2 integers", "a list of 1 to 3 numbers", "a list of at least 1 mapping".
std::string list_requirement(const Field& field, const char* one, const char* many) {
  const bool unbounded = field.list_max == std::numeric_limits<std::size_t>::max();
  std::string counts = std::to_string(field.list_min);
  if (unbounded) {
    counts = "at least " + counts;
  } else if (field.list_max != field.list_min) {
    counts += " to " + std::to_string(field.list_max);
  }
  const bool singular = unbounded ? field.list_min == 1 : field.list_max == 1;
  return "a list of " + counts + " " + (singular ? one : many);
}

}  // namespace

std::string type_requirement(const Field& field) {
  switch (field.type) {
    case FieldType::boolean: return "true or false";
    case FieldType::integer: return "an integer";
    case FieldType::number: return "a number";
    case FieldType::string: return "a string";
    case FieldType::choice: return choice_list(field.choices);
    case FieldType::integer_list: return list_requirement(field, "integer", "integers");
    case FieldType::number_list: return list_requirement(field, "number", "numbers");
    case FieldType::string_list:
      return field.choices.empty() ? list_requirement(field, "string", "strings")
                                   : list_requirement(field, "name", "names") + " from " + join(field.choices);
    case FieldType::section: return "a mapping";
    case FieldType::section_list: return list_requirement(field, "mapping", "mappings");
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
