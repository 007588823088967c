#include "pbrfit/spec/schema.hpp"

#include <algorithm>
#include <stdexcept>

namespace pbrfit::spec {
namespace {

[[noreturn]] void schema_error(const std::string& field, const std::string& problem) {
  throw std::logic_error("pbrfit::spec::Schema: field '" + field + "': " + problem);
}

template <class T>
bool list_fits(const Field& field, const Scalar& value) {
  const auto* list = std::get_if<std::vector<T>>(&value);
  return list && list->size() >= field.list_min && list->size() <= field.list_max;
}

bool default_fits_type(const Field& field, const Scalar& value) {
  switch (field.type) {
    case FieldType::boolean: return std::holds_alternative<bool>(value);
    case FieldType::integer: return std::holds_alternative<std::int64_t>(value);
    case FieldType::number: return std::holds_alternative<double>(value);
    case FieldType::string: return std::holds_alternative<std::string>(value);
    case FieldType::choice: {
      const auto* text = std::get_if<std::string>(&value);
      return text && std::ranges::find(field.choices, *text) != field.choices.end();
    }
    case FieldType::integer_list: return list_fits<std::int64_t>(field, value);
    case FieldType::number_list: return list_fits<double>(field, value);
    case FieldType::string_list: return list_fits<std::string>(field, value);
    case FieldType::section:
    case FieldType::section_list: return false;  // their defaults come from their own schema
  }
  return false;
}

Field new_field(const std::string& name, FieldType type, const std::string& doc) {
  Field field;
  field.name = name;
  field.type = type;
  field.doc = doc;
  return field;
}

Field list_field(const std::string& name, FieldType type, std::size_t min_count, std::size_t max_count,
                 const std::string& doc) {
  if (min_count > max_count) schema_error(name, "list_min exceeds list_max");
  Field field = new_field(name, type, doc);
  field.list_min = min_count;
  field.list_max = max_count;
  return field;
}

}  // namespace

Field& Field::require() {
  required = true;
  return *this;
}

Field& Field::defaults_to(Scalar value) {
  if (type == FieldType::number) {
    if (const auto* integer = std::get_if<std::int64_t>(&value)) value = static_cast<double>(*integer);
  }
  if (type == FieldType::number_list) {
    if (const auto* integers = std::get_if<std::vector<std::int64_t>>(&value))
      value = std::vector<double>(integers->begin(), integers->end());
  }
  if (!default_fits_type(*this, value)) schema_error(name, "default value does not fit the field's type");
  default_value = std::move(value);
  return *this;
}

Field& Field::range(double lo, double hi) {
  if (lo > hi) schema_error(name, "empty range");
  min = lo;
  max = hi;
  min_exclusive = false;
  return *this;
}

Field& Field::above(double lo) {
  min = lo;
  max.reset();
  min_exclusive = true;
  return *this;
}

Field& Field::at_least(double lo) {
  min = lo;
  max.reset();
  min_exclusive = false;
  return *this;
}

Field& Schema::boolean(const std::string& name, const std::string& doc) {
  return add(new_field(name, FieldType::boolean, doc));
}

Field& Schema::integer(const std::string& name, const std::string& doc) {
  return add(new_field(name, FieldType::integer, doc));
}

Field& Schema::number(const std::string& name, const std::string& doc) {
  return add(new_field(name, FieldType::number, doc));
}

Field& Schema::string(const std::string& name, const std::string& doc) {
  return add(new_field(name, FieldType::string, doc));
}

Field& Schema::choice(const std::string& name, std::vector<std::string> choices, const std::string& doc) {
  if (choices.empty()) schema_error(name, "a choice needs at least one option");
  Field field = new_field(name, FieldType::choice, doc);
  field.choices = std::move(choices);
  return add(std::move(field));
}

Field& Schema::integer_list(const std::string& name, std::size_t min_count, std::size_t max_count,
                            const std::string& doc) {
  return add(list_field(name, FieldType::integer_list, min_count, max_count, doc));
}

Field& Schema::number_list(const std::string& name, std::size_t min_count, std::size_t max_count,
                           const std::string& doc) {
  return add(list_field(name, FieldType::number_list, min_count, max_count, doc));
}

Field& Schema::string_list(const std::string& name, std::size_t min_count, std::size_t max_count,
                           const std::string& doc, std::vector<std::string> choices) {
  Field field = list_field(name, FieldType::string_list, min_count, max_count, doc);
  field.choices = std::move(choices);
  return add(std::move(field));
}

Field& Schema::section_list(const std::string& name, Schema nested, std::size_t min_count, std::size_t max_count,
                            const std::string& doc) {
  Field field = list_field(name, FieldType::section_list, min_count, max_count, doc);
  field.nested = std::make_shared<const Schema>(std::move(nested));
  return add(std::move(field));
}

Field& Schema::section(const std::string& name, Schema nested, const std::string& doc) {
  Field field = new_field(name, FieldType::section, doc);
  field.nested = std::make_shared<const Schema>(std::move(nested));
  return add(std::move(field));
}

const Field* Schema::find(const std::string& name) const {
  auto found = std::ranges::find(fields_, name, &Field::name);
  return found == fields_.end() ? nullptr : &*found;
}

Field& Schema::add(Field field) {
  if (find(field.name)) schema_error(field.name, "declared twice in schema '" + name_ + "'");
  fields_.push_back(std::move(field));
  return fields_.back();
}

}  // namespace pbrfit::spec
