#include "pbrfit/spec/schema.hpp"

#include <stdexcept>

namespace pbrfit::spec {
namespace {

[[noreturn]] void misuse(const std::string& key, const std::string& problem) {
  throw std::logic_error("pbrfit::spec::Section: key '" + key + "' " + problem);
}

template <class T>
const T& value_as(const Section::Entry& entry, const std::string& key, const char* wanted) {
  const auto* value = std::get_if<T>(&entry.value);
  if (!value) misuse(key, std::string("does not hold ") + wanted);
  return *value;
}

}  // namespace

void Section::require_declared(const std::string& key) const {
  if (!declared_.contains(key)) misuse(key, "is not in this section's schema");
}

bool Section::has(const std::string& key) const {
  require_declared(key);
  return entries_.contains(key) || sections_.contains(key) || section_lists_.contains(key);
}

bool Section::given(const std::string& key) const {
  require_declared(key);
  if (auto found = entries_.find(key); found != entries_.end()) return found->second.given;
  return given_sections_.contains(key);
}

const Section::Entry& Section::entry(const std::string& key) const {
  require_declared(key);
  auto found = entries_.find(key);
  if (found == entries_.end()) {
    misuse(key, sections_.contains(key) ? "is a section, not a value" : "has no value (check has())");
  }
  return found->second;
}

bool Section::get_bool(const std::string& key) const { return value_as<bool>(entry(key), key, "a boolean"); }

std::int64_t Section::get_int(const std::string& key) const {
  return value_as<std::int64_t>(entry(key), key, "an integer");
}

double Section::get_number(const std::string& key) const {
  const Entry& found = entry(key);
  if (const auto* integer = std::get_if<std::int64_t>(&found.value)) return static_cast<double>(*integer);
  return value_as<double>(found, key, "a number");
}

const std::string& Section::get_string(const std::string& key) const {
  return value_as<std::string>(entry(key), key, "a string");
}

const std::vector<std::int64_t>& Section::get_int_list(const std::string& key) const {
  return value_as<std::vector<std::int64_t>>(entry(key), key, "a list of integers");
}

const std::vector<double>& Section::get_number_list(const std::string& key) const {
  return value_as<std::vector<double>>(entry(key), key, "a list of numbers");
}

const std::vector<std::string>& Section::get_string_list(const std::string& key) const {
  return value_as<std::vector<std::string>>(entry(key), key, "a list of strings");
}

const std::vector<Section>& Section::get_section_list(const std::string& key) const {
  require_declared(key);
  auto found = section_lists_.find(key);
  if (found == section_lists_.end()) misuse(key, "is not a list of mappings");
  return found->second.sections;
}

const Section& Section::get_section(const std::string& key) const {
  require_declared(key);
  auto found = sections_.find(key);
  if (found == sections_.end()) {
    misuse(key, entries_.contains(key) ? "is a value, not a section" : "has no value (check has())");
  }
  return found->second;
}

SourcePosition Section::position(const std::string& key) const {
  require_declared(key);
  if (auto found = entries_.find(key); found != entries_.end()) return found->second.where;
  if (auto found = sections_.find(key); found != sections_.end()) return found->second.position();
  if (auto found = section_lists_.find(key); found != section_lists_.end()) return found->second.where;
  return position_;
}

void Section::reject(const std::string& key, const std::string& message) const {
  throw InputError(position(key), "'" + key + "' " + message);
}

void Section::declare(const std::string& key) { declared_.insert(key); }

void Section::set(const std::string& key, Entry entry) {
  declare(key);
  sections_.erase(key);
  section_lists_.erase(key);
  given_sections_.erase(key);
  entries_.insert_or_assign(key, std::move(entry));
}

void Section::set_section(const std::string& key, Section section, bool given) {
  declare(key);
  entries_.erase(key);
  section_lists_.erase(key);
  sections_.insert_or_assign(key, std::move(section));
  mark_given(key, given);
}

void Section::set_section_list(const std::string& key, std::vector<Section> sections, SourcePosition where,
                               bool given) {
  declare(key);
  entries_.erase(key);
  sections_.erase(key);
  section_lists_.insert_or_assign(key, SectionList{std::move(sections), std::move(where)});
  mark_given(key, given);
}

void Section::mark_given(const std::string& key, bool given) {
  if (given) {
    given_sections_.insert(key);
  } else {
    given_sections_.erase(key);
  }
}

}  // namespace pbrfit::spec
