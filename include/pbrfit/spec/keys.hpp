#pragma once
// Job keys declared once: each key of a kind's schema is bound, where it is declared, to what it fills in
// the kind's settings struct, so a key's name, type, range, default, meaning and destination are written
// in one place and no code reads a key back by its name.
//
//   spec::Keys<DfgSettings> keys("lut");
//   keys.boolean("cloth", "also tabulate the cloth channel", &DfgSettings::cloth).defaults_to(false);
//   keys.choice("roughness", {{"perceptual", Rough::perceptual}, {"linear", Rough::linear}}, "the axis",
//               &DfgSettings::roughness).defaults_to(std::string("perceptual"));
//   keys.integer_list("resolution", 2, 2, "entries along [n_dot_v, roughness]",
//                     [](DfgSettings& s, const std::vector<std::int64_t>& r) { s.columns = r[0]; s.rows = r[1]; });
//   keys.check("resolution", [](DfgSettings& s) { return s.rows < 2 ? "needs 2 rows" : ""; });
//   DfgSettings settings = keys.read(section);  // section: validated by keys.schema()
//
// What a key fills is one of
//  - a member pointer: assigned with a conversion to the member's type (an integer to any arithmetic type,
//    a list element by element, a choice to its bound value);
//  - a member pointer to std::optional<T>: set only when the key is written in the file (its default does
//    not count), so the kind can tell "left out" from "written";
//  - a member pointer to Written<T>: the value (written or default) and whether it was written;
//  - a member pointer to Located<T>: that, with the key's name and position (the section's when absent),
//    for checks that refuse the job at a key of a nested section (located.reject("must ...")) once the
//    settings around it are known;
//  - a callable (Settings&, const Value&), for a key that fills several members or a nested engine option.
// Besides, keys.list_written(&Settings::written) lists the keys the file wrote (WrittenKey: name, position),
// for a section whose keys are read by some users and refused by others (a sweep's `objective`).
// Value is the key's C++ type: bool, std::int64_t, double, std::string (string), the choice's bound type,
// std::vector of std::int64_t, double or std::string; a nested Keys' settings type for a section (or
// std::vector of them for a section list). A key without a value (optional, no default, left out) fills
// nothing. Checks run after every key is filled, in the order declared, and may complete the settings
// (load a file a key names); a non-empty message refuses the job at the check's key ("'KEY' MESSAGE",
// FILE:LINE:COL); an InputError a check throws (a problem inside a file) passes through. Declaring a check for a key the schema lacks, or a key twice, throws std::logic_error.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "pbrfit/spec/schema.hpp"

namespace pbrfit::spec {

// A key's value and whether the job file wrote it (false: the default).
template <class T>
struct Written {
  T value{};
  bool written = false;
};

// A key's value, whether the job file wrote it, and where: its key's name and position.
template <class T>
struct Located {
  T value{};
  bool written = false;
  std::string key;
  SourcePosition where;
  // Throws InputError "'KEY' MESSAGE" at the key's position (as Section::reject does).
  [[noreturn]] void reject(const std::string& message) const { throw InputError(where, "'" + key + "' " + message); }
};

// A key the job file wrote, and where.
struct WrittenKey {
  std::string key;
  SourcePosition where;
  [[noreturn]] void reject(const std::string& message) const { throw InputError(where, "'" + key + "' " + message); }
};

namespace keys_detail {

template <class T>
struct is_written : std::false_type {};
template <class T>
struct is_written<Written<T>> : std::true_type {};
template <class T>
struct is_located : std::false_type {};
template <class T>
struct is_located<Located<T>> : std::true_type {};

template <class T>
struct is_optional : std::false_type {};
template <class T>
struct is_optional<std::optional<T>> : std::true_type {};

template <class T>
struct is_vector : std::false_type {};
template <class T, class A>
struct is_vector<std::vector<T, A>> : std::true_type {};

// `value` converted to a member of type M.
template <class M, class V>
M converted(const V& value) {
  if constexpr (is_vector<M>::value && is_vector<V>::value) {
    M out;
    for (const auto& element : value) out.push_back(converted<typename M::value_type>(element));
    return out;
  } else if constexpr (std::is_arithmetic_v<M> && std::is_arithmetic_v<V>) {
    return static_cast<M>(value);
  } else {
    return M(value);
  }
}

}  // namespace keys_detail

template <class Settings>
class Keys {
 public:
  explicit Keys(std::string name) : schema_(std::move(name)) {}

  template <class Into>
  Field& boolean(const std::string& name, const std::string& doc, Into into) {
    return bind<bool>(schema_.boolean(name, doc), std::move(into));
  }
  template <class Into>
  Field& integer(const std::string& name, const std::string& doc, Into into) {
    return bind<std::int64_t>(schema_.integer(name, doc), std::move(into));
  }
  template <class Into>
  Field& number(const std::string& name, const std::string& doc, Into into) {
    return bind<double>(schema_.number(name, doc), std::move(into));
  }
  template <class Into>
  Field& string(const std::string& name, const std::string& doc, Into into) {
    return bind<std::string>(schema_.string(name, doc), std::move(into));
  }
  // A choice among names, filling its name.
  template <class Into>
  Field& choice(const std::string& name, std::vector<std::string> choices, const std::string& doc, Into into) {
    return bind<std::string>(schema_.choice(name, std::move(choices), doc), std::move(into));
  }
  // A choice among names, each bound to a value of type T, filling the value.
  template <class T, class Into>
  Field& choice(const std::string& name, std::vector<std::pair<std::string, T>> named, const std::string& doc,
                Into into) {
    std::vector<std::string> names;
    for (const auto& [choice, value] : named) names.push_back(choice);
    Field& field = schema_.choice(name, std::move(names), doc);
    const auto to_value = [named = std::move(named)](const std::string& choice) {
      for (const auto& [n, value] : named)
        if (n == choice) return value;
      throw std::logic_error("the schema let an unknown choice through: " + choice);
    };
    add_filler(name, [to_value, into = std::move(into)](Settings& s, const Section& section, const std::string& key) {
      fill<T>(s, section, key, into, [&] { return to_value(section.get_string(key)); });
    });
    return field;
  }
  template <class Into>
  Field& integer_list(const std::string& name, std::size_t min_count, std::size_t max_count, const std::string& doc,
                      Into into) {
    return bind<std::vector<std::int64_t>>(schema_.integer_list(name, min_count, max_count, doc), std::move(into));
  }
  template <class Into>
  Field& number_list(const std::string& name, std::size_t min_count, std::size_t max_count, const std::string& doc,
                     Into into) {
    return bind<std::vector<double>>(schema_.number_list(name, min_count, max_count, doc), std::move(into));
  }
  template <class Into>
  Field& string_list(const std::string& name, std::size_t min_count, std::size_t max_count, const std::string& doc,
                     Into into, std::vector<std::string> choices = {}) {
    return bind<std::vector<std::string>>(schema_.string_list(name, min_count, max_count, doc, std::move(choices)),
                                          std::move(into));
  }
  // A nested mapping with keys of its own, read into a Nested and handed to `into`.
  template <class Nested, class Into>
  Field& section(const std::string& name, const Keys<Nested>& nested, const std::string& doc, Into into) {
    Field& field = schema_.section(name, nested.schema(), doc);
    add_filler(name, [nested = std::make_shared<Keys<Nested>>(nested), into = std::move(into)](
                         Settings& s, const Section& section, const std::string& key) {
      fill<Nested>(s, section, key, into, [&] { return nested->read(section.get_section(key)); });
    });
    return field;
  }
  template <class Nested, class Into>
  Field& section_list(const std::string& name, const Keys<Nested>& nested, std::size_t min_count,
                      std::size_t max_count, const std::string& doc, Into into) {
    Field& field = schema_.section_list(name, nested.schema(), min_count, max_count, doc);
    add_filler(name, [nested = std::make_shared<Keys<Nested>>(nested), into = std::move(into)](
                         Settings& s, const Section& section, const std::string& key) {
      fill<std::vector<Nested>>(s, section, key, into, [&] {
        std::vector<Nested> out;
        for (const Section& item : section.get_section_list(key)) out.push_back(nested->read(item));
        return out;
      });
    });
    return field;
  }

  // A rule over the filled settings; a non-empty message refuses the job at `key`. The rule is called as
  // rule(settings) or, when it takes one, rule(settings, where), `where` being the key's position (for
  // errors found in what a key names, such as a column of a file).
  template <class Rule>
  void check(const std::string& key, Rule rule) {
    if (!schema_.find(key)) throw std::logic_error("a check of '" + schema_.name() + "' names no key: " + key);
    checks_.push_back({key, [rule = std::move(rule)](Settings& s, const Section& section, const std::string& k) {
                         if constexpr (std::is_invocable_v<Rule&, Settings&, const SourcePosition&>)
                           return std::string(rule(s, section.position(k)));
                         else
                           return std::string(rule(s));
                       }});
  }
  // Fills `into` with the keys the section writes, in the schema's order.
  void list_written(std::vector<WrittenKey> Settings::*into) { written_ = into; }
  const Schema& schema() const { return schema_; }

  // The settings a validated section describes, starting from `settings`.
  Settings read(const Section& section, Settings settings = {}) const {
    for (const auto& [key, filler] : fillers_) filler(settings, section, key);
    if (written_)
      for (const Field& field : schema_.fields())
        if (section.given(field.name)) (settings.*written_).push_back({field.name, section.position(field.name)});
    for (const auto& [key, rule] : checks_) {
      const std::string message = rule(settings, section, key);
      if (!message.empty()) section.reject(key, message);
    }
    return settings;
  }

 private:
  using Filler = std::function<void(Settings&, const Section&, const std::string&)>;
  using Rule = std::function<std::string(Settings&, const Section&, const std::string&)>;

  template <class Value, class Into>
  Field& bind(Field& field, Into into) {
    add_filler(field.name, [into = std::move(into)](Settings& s, const Section& section, const std::string& key) {
      fill<Value>(s, section, key, into, [&] { return value_of<Value>(section, key); });
    });
    return field;
  }

  void add_filler(const std::string& key, Filler filler) { fillers_.emplace_back(key, std::move(filler)); }

  template <class Value>
  static Value value_of(const Section& section, const std::string& key) {
    if constexpr (std::is_same_v<Value, bool>) return section.get_bool(key);
    else if constexpr (std::is_same_v<Value, std::int64_t>) return section.get_int(key);
    else if constexpr (std::is_same_v<Value, double>) return section.get_number(key);
    else if constexpr (std::is_same_v<Value, std::string>) return section.get_string(key);
    else if constexpr (std::is_same_v<Value, std::vector<std::int64_t>>) return section.get_int_list(key);
    else if constexpr (std::is_same_v<Value, std::vector<double>>) return section.get_number_list(key);
    else return section.get_string_list(key);
  }

  // Hands the key's value (made by `make` only when it has one) to `into`.
  template <class Value, class Into, class Make>
  static void fill(Settings& s, const Section& section, const std::string& key, const Into& into, Make make) {
    if constexpr (std::is_member_object_pointer_v<Into>) {
      using Member = std::remove_cvref_t<decltype(s.*into)>;
      if constexpr (keys_detail::is_located<Member>::value) {  // located even when absent, to reject at
        (s.*into).key = key;
        (s.*into).where = section.position(key);
      }
    }
    if (!section.has(key)) return;
    if constexpr (std::is_member_object_pointer_v<Into>) {
      using Member = std::remove_cvref_t<decltype(s.*into)>;
      if constexpr (keys_detail::is_optional<Member>::value) {
        if (section.given(key)) s.*into = keys_detail::converted<typename Member::value_type>(make());
      } else if constexpr (keys_detail::is_written<Member>::value) {
        s.*into = {keys_detail::converted<decltype(Member::value)>(make()), section.given(key)};
      } else if constexpr (keys_detail::is_located<Member>::value) {
        s.*into = {keys_detail::converted<decltype(Member::value)>(make()), section.given(key), key,
                   section.position(key)};
      } else {
        s.*into = keys_detail::converted<Member>(make());
      }
    } else {
      into(s, make());
    }
  }

  Schema schema_;
  std::vector<std::pair<std::string, Filler>> fillers_;
  std::vector<std::pair<std::string, Rule>> checks_;
  std::vector<WrittenKey> Settings::*written_ = nullptr;
};

}  // namespace pbrfit::spec
