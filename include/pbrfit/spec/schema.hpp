#pragma once
// Declarative schema for one YAML mapping of a job file: keys, types, ranges, choices, defaults, docs.
// Validation is strict: unknown keys (with the closest valid key suggested), wrong types, out-of-range
// numbers, bad choices, missing required keys and duplicate keys are InputErrors naming FILE:LINE:COL.
// A key written with an empty or null value (`key:`, `key: ~`, `key: null`) is a wrong-type error,
// never "absent": only leaving the key out selects its default.
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "pbrfit/core/error.hpp"

namespace pbrfit::spec {

class Schema;
class Section;

enum class FieldType { boolean, integer, number, string, choice, integer_list, number_list, string_list, section,
                       section_list };

// No upper limit on a list's length (beyond the job file's size).
inline constexpr std::size_t unbounded = std::numeric_limits<std::size_t>::max();

using Scalar = std::variant<bool, std::int64_t, double, std::string, std::vector<std::int64_t>, std::vector<double>,
                            std::vector<std::string>>;

struct Field {
  std::string name;
  FieldType type = FieldType::string;
  std::string doc;
  bool required = false;
  std::optional<Scalar> default_value;
  std::optional<double> min, max;            // inclusive bounds for integer, number and list elements
  bool min_exclusive = false;
  std::vector<std::string> choices;          // choice; string_list: allowed elements (empty: any string)
  std::size_t list_min = 0, list_max = 0;    // element counts of every list type
  std::shared_ptr<const Schema> nested;      // section and section_list: the schema of each mapping

  // Fluent setters; each returns *this.
  Field& require();
  // The value's alternative must match the type (an integer is accepted for a number field, a
  // choice's default must be one of its choices); anything else throws std::logic_error.
  Field& defaults_to(Scalar value);
  Field& range(double lo, double hi);
  Field& above(double lo);                   // lo exclusive, no upper bound
  Field& at_least(double lo);                // lo inclusive, no upper bound
};

class Schema {
 public:
  explicit Schema(std::string name) : name_(std::move(name)) {}

  // Each adder returns the new field for the fluent setters; the reference is valid until the next
  // field is added. Adding a name twice throws std::logic_error.
  Field& boolean(const std::string& name, const std::string& doc);
  Field& integer(const std::string& name, const std::string& doc);
  Field& number(const std::string& name, const std::string& doc);
  Field& string(const std::string& name, const std::string& doc);
  Field& choice(const std::string& name, std::vector<std::string> choices, const std::string& doc);
  Field& integer_list(const std::string& name, std::size_t min_count, std::size_t max_count,
                      const std::string& doc);
  Field& number_list(const std::string& name, std::size_t min_count, std::size_t max_count, const std::string& doc);
  // choices empty: any non-empty string; else each element must be one of them.
  Field& string_list(const std::string& name, std::size_t min_count, std::size_t max_count, const std::string& doc,
                     std::vector<std::string> choices = {});
  // A nested mapping; its defaults apply when the key is absent (unless the field is required).
  // An absent optional section whose schema has required keys cannot be defaulted: has() is false.
  Field& section(const std::string& name, Schema nested, const std::string& doc);
  // A list of mappings, each validated by `nested`; an absent key defaults to the empty list when
  // min_count is 0 (otherwise it is missing, like a required key).
  Field& section_list(const std::string& name, Schema nested, std::size_t min_count, std::size_t max_count,
                      const std::string& doc);

  const std::string& name() const { return name_; }
  const std::vector<Field>& fields() const { return fields_; }
  const Field* find(const std::string& name) const;

 private:
  Field& add(Field field);
  std::string name_;
  std::vector<Field> fields_;
};

// A validated mapping: every schema key present (explicitly or by default) with its type checked.
// Every accessor throws std::logic_error for a key the schema does not declare, and the getters also
// for a key without a value (check has() first for optional keys without a default) or of another type.
class Section {
 public:
  bool has(const std::string& key) const;  // present in the file or defaulted
  bool given(const std::string& key) const;  // written in the file
  bool get_bool(const std::string& key) const;
  std::int64_t get_int(const std::string& key) const;
  double get_number(const std::string& key) const;  // integers are accepted for numbers
  const std::string& get_string(const std::string& key) const;  // also for choices
  const std::vector<std::int64_t>& get_int_list(const std::string& key) const;
  const std::vector<double>& get_number_list(const std::string& key) const;  // integers widened
  const std::vector<std::string>& get_string_list(const std::string& key) const;
  const Section& get_section(const std::string& key) const;
  const std::vector<Section>& get_section_list(const std::string& key) const;

  // Where the key's value is written; the section's own position when the key was defaulted.
  SourcePosition position(const std::string& key) const;
  const SourcePosition& position() const { return position_; }
  // Throws InputError at position(key) with the message "'KEY' MESSAGE" (for cross-field checks).
  [[noreturn]] void reject(const std::string& key, const std::string& message) const;

  // Construction, for the validator.
  struct Entry {
    Scalar value;
    SourcePosition where;
    bool given = false;
  };
  // set() and set_section() also declare the key; declare() alone adds a schema key without a value.
  Section() = default;
  explicit Section(SourcePosition where) : position_(std::move(where)) {}
  void declare(const std::string& key);
  void set(const std::string& key, Entry entry);
  void set_section(const std::string& key, Section section, bool given = true);
  void set_section_list(const std::string& key, std::vector<Section> sections, SourcePosition where, bool given);

 private:
  const Entry& entry(const std::string& key) const;
  void mark_given(const std::string& key, bool given);
  void require_declared(const std::string& key) const;
  SourcePosition position_;
  std::set<std::string> declared_;        // every schema key, with or without a value
  std::map<std::string, Entry> entries_;
  std::map<std::string, Section> sections_;
  std::set<std::string> given_sections_;  // the keys of sections_ and section_lists_ written in the file
  struct SectionList {
    std::vector<Section> sections;
    SourcePosition where;
  };
  std::map<std::string, SectionList> section_lists_;
};

// The closest candidate by edit distance, or "" when none is plausibly meant: the Levenshtein distance
// must be at most 2 or at most a third of the word's length, and smaller than the word's length.
// Ties go to the earliest candidate.
std::string closest_match(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace pbrfit::spec
