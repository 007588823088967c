#include "yaml_validation.hpp"

#include <algorithm>
#include <optional>
#include <set>
#include <vector>

#include "message_text.hpp"
#include "scalar_syntax.hpp"

namespace pbrfit::spec {
namespace {

std::string child_path(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

// "'KEY' must be REQUIREMENT, got WHAT" at where.
[[noreturn]] void reject_value(const SourcePosition& where, const std::string& subject,
                               const std::string& requirement, const std::string& what) {
  throw InputError(where, subject + " must be " + requirement + ", got " + what);
}

[[noreturn]] void reject_wrong_type(const Field& field, const YAML::Node& key, const YAML::Node& value,
                                    const YamlSource& source) {
  reject_value(source.value_position(key, value), quote(field.name), type_requirement(field),
               source.describe(value));
}

void check_range(const Field& field, const std::string& subject, double value, const std::string& written,
                 const SourcePosition& where) {
  if (!in_range(field, value)) reject_value(where, subject, range_requirement(field), shortened(written));
}

// An integer written at value; subject names it in messages ("'seed'", "'resolution' item 2").
std::int64_t checked_integer(const Field& field, const std::string& subject, const YAML::Node& value,
                             const SourcePosition& where, const YamlSource& source) {
  const std::optional<std::int64_t> integer =
      value.IsScalar() ? parse_integer(value.Scalar()) : std::nullopt;
  if (!integer) {
    const bool too_long = value.IsScalar() && has_integer_syntax(value.Scalar());
    reject_value(where, subject, too_long ? "an integer that fits in 64 bits" : "an integer",
                 too_long ? shortened(value.Scalar()) : source.describe(value));
  }
  check_range(field, subject, static_cast<double>(*integer), value.Scalar(), where);
  return *integer;
}

double checked_number(const Field& field, const YAML::Node& key, const YAML::Node& value,
                      const YamlSource& source) {
  const std::optional<double> number = value.IsScalar() ? parse_number(value.Scalar()) : std::nullopt;
  if (!number) reject_wrong_type(field, key, value, source);
  check_range(field, quote(field.name), *number, value.Scalar(), source.position(value.Mark()));
  return *number;
}

bool checked_boolean(const Field& field, const YAML::Node& key, const YAML::Node& value,
                     const YamlSource& source) {
  bool flag = false;
  if (!value.IsScalar() || !YAML::convert<bool>::decode(value, flag)) {
    reject_wrong_type(field, key, value, source);
  }
  return flag;
}

std::string checked_string(const Field& field, const YAML::Node& key, const YAML::Node& value,
                           const YamlSource& source) {
  if (!value.IsScalar()) reject_wrong_type(field, key, value, source);
  return value.Scalar();
}

std::string checked_choice(const Field& field, const YAML::Node& key, const YAML::Node& value,
                           const YamlSource& source) {
  if (value.IsScalar()) {
    for (const std::string& choice : field.choices) {
      if (value.Scalar() == choice) return choice;
    }
  }
  const std::string hint = value.IsScalar() ? suggestion(value.Scalar(), field.choices) : "";
  throw InputError(source.value_position(key, value), quote(field.name) + " must be " +
                                                          type_requirement(field) + "; got " +
                                                          source.describe(value) + hint);
}

std::string count_of_items(std::size_t count) {
  if (count == 0) return "an empty list";
  return "a list of " + std::to_string(count) + (count == 1 ? " item" : " items");
}

void check_list_size(const Field& field, const YAML::Node& key, const YAML::Node& value, const YamlSource& source) {
  if (!value.IsSequence()) reject_wrong_type(field, key, value, source);
  if (value.size() < field.list_min || value.size() > field.list_max) {
    reject_value(source.position(value.Mark()), quote(field.name), type_requirement(field),
                 count_of_items(value.size()));
  }
}

std::string item_subject(const Field& field, std::size_t index) {
  return quote(field.name) + " item " + std::to_string(index + 1);
}

std::vector<std::int64_t> checked_integer_list(const Field& field, const YAML::Node& key,
                                               const YAML::Node& value, const YamlSource& source) {
  check_list_size(field, key, value, source);
  std::vector<std::int64_t> integers;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const YAML::Node item = value[i];
    integers.push_back(checked_integer(field, item_subject(field, i), item, source.position(item.Mark()), source));
  }
  return integers;
}

std::vector<double> checked_number_list(const Field& field, const YAML::Node& key, const YAML::Node& value,
                                        const YamlSource& source) {
  check_list_size(field, key, value, source);
  std::vector<double> numbers;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const YAML::Node item = value[i];
    const SourcePosition where = source.position(item.Mark());
    const std::optional<double> number = item.IsScalar() ? parse_number(item.Scalar()) : std::nullopt;
    if (!number) reject_value(where, item_subject(field, i), "a number", source.describe(item));
    check_range(field, item_subject(field, i), *number, item.Scalar(), where);
    numbers.push_back(*number);
  }
  return numbers;
}

std::vector<std::string> checked_string_list(const Field& field, const YAML::Node& key, const YAML::Node& value,
                                             const YamlSource& source) {
  check_list_size(field, key, value, source);
  std::vector<std::string> texts;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const YAML::Node item = value[i];
    const SourcePosition where = source.position(item.Mark());
    if (!item.IsScalar() || item.Scalar().empty()) {
      reject_value(where, item_subject(field, i), "a non-empty string", source.describe(item));
    }
    if (!field.choices.empty() && std::ranges::find(field.choices, item.Scalar()) == field.choices.end()) {
      throw InputError(where, item_subject(field, i) + " must be " + choice_list(field.choices) + "; got " +
                                  source.describe(item) + suggestion(item.Scalar(), field.choices));
    }
    texts.push_back(item.Scalar());
  }
  return texts;
}

Scalar checked_scalar(const Field& field, const YAML::Node& key, const YAML::Node& value,
                      const YamlSource& source) {
  switch (field.type) {
    case FieldType::boolean: return checked_boolean(field, key, value, source);
    case FieldType::integer:
      return checked_integer(field, quote(field.name), value, source.value_position(key, value), source);
    case FieldType::number: return checked_number(field, key, value, source);
    case FieldType::string: return checked_string(field, key, value, source);
    case FieldType::choice: return checked_choice(field, key, value, source);
    case FieldType::integer_list: return checked_integer_list(field, key, value, source);
    case FieldType::number_list: return checked_number_list(field, key, value, source);
    case FieldType::string_list: return checked_string_list(field, key, value, source);
    case FieldType::section:
    case FieldType::section_list: break;
  }
  throw std::logic_error("pbrfit::spec: section field '" + field.name + "' validated as a value");
}

[[noreturn]] void reject_unknown_key(const std::string& key, const YAML::Node& key_node, const Schema& schema,
                                     const std::string& path, const YamlSource& source) {
  std::vector<std::string> valid_keys;
  for (const Field& field : schema.fields()) valid_keys.push_back(field.name);
  std::string hint = suggestion(key, valid_keys);
  if (hint.empty()) hint = "; valid keys: " + join(valid_keys);
  throw InputError(source.position(key_node.Mark()),
                   "unknown key " + quote(key) + " in " + quote(display_path(path)) + hint);
}

// The section an absent key stands for: all defaults, or nullopt when a required key has none.
std::optional<Section> defaulted_section(const Schema& schema, const SourcePosition& where) {
  Section section(where);
  for (const Field& field : schema.fields()) {
    section.declare(field.name);
    if (field.required || (field.type == FieldType::section_list && field.list_min > 0)) return std::nullopt;
    if (field.type == FieldType::section_list) {
      section.set_section_list(field.name, {}, where, false);
    } else if (field.type == FieldType::section) {
      if (auto nested = defaulted_section(*field.nested, where)) {
        section.set_section(field.name, std::move(*nested), false);
      }
    } else if (field.default_value) {
      section.set(field.name, Section::Entry{*field.default_value, where, false});
    }
  }
  return section;
}

void fill_absent_field(Section& section, const Field& field, const std::string& path) {
  if (field.required || (field.type == FieldType::section_list && field.list_min > 0)) {
    throw InputError(section.position(), "missing required key " + quote(field.name) + " in " +
                                             quote(display_path(path)));
  }
  if (field.type == FieldType::section_list) {
    section.set_section_list(field.name, {}, section.position(), false);
  } else if (field.type == FieldType::section) {
    if (auto nested = defaulted_section(*field.nested, section.position())) {
      section.set_section(field.name, std::move(*nested), false);
    }
  } else if (field.default_value) {
    section.set(field.name, Section::Entry{*field.default_value, section.position(), false});
  }
}

Section validated_section(const Field& field, const YAML::Node& key, const YAML::Node& value,
                          const std::string& path, const YamlSource& source) {
  if (!value.IsMap()) reject_wrong_type(field, key, value, source);
  return validate_mapping(value, *field.nested, child_path(path, field.name), source);
}

// Each item a mapping of the nested schema, named "PATH.KEY[N]" (1-based) in messages.
std::vector<Section> validated_section_list(const Field& field, const YAML::Node& key, const YAML::Node& value,
                                            const std::string& path, const YamlSource& source) {
  check_list_size(field, key, value, source);
  std::vector<Section> sections;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const YAML::Node item = value[i];
    const std::string item_path = child_path(path, field.name) + "[" + std::to_string(i + 1) + "]";
    if (!item.IsMap()) {
      reject_value(source.position(item.Mark()), quote(item_path), "a mapping", source.describe(item));
    }
    sections.push_back(validate_mapping(item, *field.nested, item_path, source));
  }
  return sections;
}

// Aliases can make a document a graph. The walk rejects an alias of a mapping or list that encloses
// it (a cycle), and gives up after visiting more nodes than the text has characters: without aliases
// every node takes at least one character, so only alias chains that multiply ("billion laughs") get
// there.
class DuplicateKeyWalk {
 public:
  explicit DuplicateKeyWalk(const YamlSource& source)
      : source_(source), visits_left_(source.text().size() + 64) {}

  // reached_at: the key (or, at the top, the document) through which node is reached.
  void walk(const YAML::Node& node, const std::string& path, const YAML::Mark& reached_at) {
    if (!node.IsMap() && !node.IsSequence()) return;
    enter(node, path, reached_at);
    ancestors_.push_back(node);
    if (node.IsSequence()) {
      for (std::size_t i = 0; i < node.size(); ++i) {
        walk(node[i], path + "[" + std::to_string(i) + "]", reached_at);
      }
    } else {
      walk_mapping(node, path);
    }
    ancestors_.pop_back();
  }

 private:
  void enter(const YAML::Node& node, const std::string& path, const YAML::Mark& reached_at) {
    for (const YAML::Node& ancestor : ancestors_) {
      if (node.is(ancestor)) {
        throw InputError(source_.position(reached_at),
                         "the value of " + quote(display_path(path)) +
                             " is an alias of a mapping or list that contains it");
      }
    }
    if (visits_left_-- == 0) {
      throw InputError(source_.position(reached_at), "aliases expand the job file to too many values");
    }
  }

  void walk_mapping(const YAML::Node& mapping, const std::string& path) {
    std::set<std::string> seen;
    for (const auto& pair : mapping) {
      if (!pair.first.IsScalar()) continue;  // reported by validate_mapping
      const std::string& key = pair.first.Scalar();
      if (!seen.insert(key).second) {
        throw InputError(source_.position(pair.first.Mark()),
                         "duplicate key " + quote(key) + " in " + quote(display_path(path)));
      }
      walk(pair.second, child_path(path, key), pair.first.Mark());
    }
  }

  const YamlSource& source_;
  std::size_t visits_left_;
  std::vector<YAML::Node> ancestors_;  // the mappings and lists enclosing the current node
};

}  // namespace

std::string display_path(const std::string& path) { return path.empty() ? "job" : path; }

std::string key_name(const YAML::Node& key, const std::string& path, const YamlSource& source) {
  if (!key.IsScalar()) {
    throw InputError(source.position(key.Mark()), "a key in " + quote(display_path(path)) +
                                                      " must be a name, got " + source.describe(key));
  }
  return key.Scalar();
}

void reject_duplicate_keys(const YAML::Node& node, const std::string& path, const YamlSource& source) {
  DuplicateKeyWalk(source).walk(node, path, node.Mark());
}

Section::Entry validate_value(const Field& field, const YAML::Node& key, const YAML::Node& value,
                              const YamlSource& source) {
  return Section::Entry{checked_scalar(field, key, value, source), source.position(value.Mark()), true};
}

Section validate_mapping(const YAML::Node& mapping, const Schema& schema, const std::string& path,
                         const YamlSource& source) {
  Section section(source.position(mapping.Mark()));
  for (const Field& field : schema.fields()) section.declare(field.name);
  for (const auto& pair : mapping) {
    const std::string key = key_name(pair.first, path, source);
    const Field* field = schema.find(key);
    if (!field) reject_unknown_key(key, pair.first, schema, path, source);
    if (field->type == FieldType::section) {
      section.set_section(key, validated_section(*field, pair.first, pair.second, path, source));
    } else if (field->type == FieldType::section_list) {
      section.set_section_list(key, validated_section_list(*field, pair.first, pair.second, path, source),
                               source.position(pair.second.Mark()), true);
    } else {
      section.set(key, validate_value(*field, pair.first, pair.second, source));
    }
  }
  for (const Field& field : schema.fields()) {
    if (!section.given(field.name)) fill_absent_field(section, field, path);
  }
  return section;
}

}  // namespace pbrfit::spec
