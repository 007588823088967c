#include <catch2/catch_test_macros.hpp>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "pbrfit/spec/job_spec.hpp"
#include "pbrfit/spec/schema.hpp"

using pbrfit::InputError;
using pbrfit::SourcePosition;
using pbrfit::spec::Section;

namespace {

Section hand_built_section() {
  Section section(SourcePosition{"f.yaml", 3, 1});
  section.declare("optional");
  section.set("count", Section::Entry{std::int64_t{4}, SourcePosition{"f.yaml", 4, 10}, true});
  section.set("ratio", Section::Entry{2.5, SourcePosition{"f.yaml", 5, 10}, false});
  section.set("mode", Section::Entry{std::string("fast"), SourcePosition{"f.yaml", 6, 9}, true});
  section.set("on", Section::Entry{true, SourcePosition{"f.yaml", 7, 7}, true});
  section.set("size", Section::Entry{std::vector<std::int64_t>{8, 16}, SourcePosition{"f.yaml", 8, 9}, true});
  section.set_section("inner", Section(SourcePosition{"f.yaml", 10, 3}), false);
  return section;
}

}  // namespace

TEST_CASE("section getters return what was set") {
  const Section section = hand_built_section();
  CHECK(section.get_int("count") == 4);
  CHECK(section.get_number("count") == 4.0);  // integers are numbers
  CHECK(section.get_number("ratio") == 2.5);
  CHECK(section.get_string("mode") == "fast");
  CHECK(section.get_bool("on"));
  CHECK(section.get_int_list("size") == std::vector<std::int64_t>{8, 16});
  CHECK(section.get_section("inner").position().line == 10);
}

TEST_CASE("section has, given and position") {
  const Section section = hand_built_section();
  CHECK(section.has("count"));
  CHECK(section.given("count"));
  CHECK_FALSE(section.given("ratio"));
  CHECK(section.has("inner"));
  CHECK_FALSE(section.given("inner"));
  CHECK_FALSE(section.has("optional"));
  CHECK_FALSE(section.given("optional"));
  CHECK(section.position("count").line == 4);
  CHECK(section.position("count").column == 10);
  CHECK(section.position("inner").line == 10);
  CHECK(section.position("optional").line == 3);  // falls back to the section's own position
  CHECK(section.position().line == 3);
}

TEST_CASE("section misuse is a logic_error") {
  const Section section = hand_built_section();
  CHECK_THROWS_AS(section.get_int("nope"), std::logic_error);       // not in the schema
  CHECK_THROWS_AS(section.has("nope"), std::logic_error);
  CHECK_THROWS_AS(section.position("nope"), std::logic_error);
  CHECK_THROWS_AS(section.get_int("optional"), std::logic_error);   // no value
  CHECK_THROWS_AS(section.get_int("ratio"), std::logic_error);      // wrong type
  CHECK_THROWS_AS(section.get_string("count"), std::logic_error);
  CHECK_THROWS_AS(section.get_bool("mode"), std::logic_error);
  CHECK_THROWS_AS(section.get_int_list("count"), std::logic_error);
  CHECK_THROWS_AS(section.get_section("count"), std::logic_error);  // a value, not a section
  CHECK_THROWS_AS(section.get_int("inner"), std::logic_error);      // a section, not a value
  CHECK_THROWS_AS(Section().get_int("anything"), std::logic_error);
}

TEST_CASE("reject reports at the key's value, or at the section when defaulted") {
  const Section section = hand_built_section();
  try {
    section.reject("count", "must be even");
    FAIL("no throw");
  } catch (const InputError& error) {
    CHECK(std::string(error.what()) == "f.yaml:4:10: error: 'count' must be even");
  }
  try {
    section.reject("optional", "is needed when count is 4");
    FAIL("no throw");
  } catch (const InputError& error) {
    CHECK(std::string(error.what()) == "f.yaml:3:1: error: 'optional' is needed when count is 4");
  }
}

TEST_CASE("a JobSpec can be built piecewise") {
  pbrfit::spec::JobSpec spec{};  // Section's default constructor is not explicit
  spec.name = "x";
  CHECK(spec.kind_section.position().line == 0);
}
