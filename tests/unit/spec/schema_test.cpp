#include <catch2/catch_test_macros.hpp>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "pbrfit/spec/schema.hpp"

using pbrfit::spec::Field;
using pbrfit::spec::FieldType;
using pbrfit::spec::Schema;

TEST_CASE("schema adders record type, doc and order") {
  Schema schema("demo");
  schema.boolean("flag", "A flag.");
  schema.choice("mode", {"fast", "exact"}, "A mode.");
  schema.integer_list("size", 1, 3, "A size.");
  Schema inner("inner");
  inner.integer("count", "A count.");
  schema.section("inner", inner, "A section.");

  REQUIRE(schema.fields().size() == 4);
  CHECK(schema.fields()[0].name == "flag");
  CHECK(schema.fields()[0].type == FieldType::boolean);
  CHECK(schema.fields()[0].doc == "A flag.");
  CHECK(schema.find("mode")->choices == std::vector<std::string>{"fast", "exact"});
  CHECK(schema.find("size")->list_min == 1);
  CHECK(schema.find("size")->list_max == 3);
  REQUIRE(schema.find("inner")->nested);
  CHECK(schema.find("inner")->nested->find("count"));
  CHECK(schema.find("missing") == nullptr);
}

TEST_CASE("bounds setters") {
  Schema schema("demo");
  const Field ranged = schema.integer("a", "").range(1, 9);
  CHECK((ranged.min == 1.0 && ranged.max == 9.0 && !ranged.min_exclusive));
  const Field above = schema.number("b", "").above(0);
  CHECK((above.min == 0.0 && !above.max && above.min_exclusive));
  const Field at_least = schema.number("c", "").at_least(2);
  CHECK((at_least.min == 2.0 && !at_least.max && !at_least.min_exclusive));
  CHECK(schema.number("d", "").require().required);
  CHECK_THROWS_AS(schema.number("e", "").range(2, 1), std::logic_error);
}

TEST_CASE("defaults must fit the field") {
  Schema schema("demo");
  CHECK(std::get<double>(*schema.number("n", "").defaults_to(3).default_value) == 3.0);  // integer widened
  CHECK(std::get<std::string>(*schema.choice("m", {"a", "b"}, "").defaults_to("b").default_value) == "b");
  CHECK_THROWS_AS(schema.integer("i", "").defaults_to(1.5), std::logic_error);
  CHECK_THROWS_AS(schema.boolean("b", "").defaults_to(std::string("yes")), std::logic_error);
  CHECK_THROWS_AS(schema.choice("c", {"a", "b"}, "").defaults_to("z"), std::logic_error);
  const std::vector<std::int64_t> one_item = {1};
  CHECK_THROWS_AS(schema.integer_list("l", 2, 2, "").defaults_to(one_item), std::logic_error);
  CHECK_THROWS_AS(schema.section("s", Schema("s"), "").defaults_to(true), std::logic_error);
}

TEST_CASE("schema programmer errors") {
  Schema schema("demo");
  schema.integer("a", "");
  CHECK_THROWS_AS(schema.number("a", ""), std::logic_error);
  CHECK_THROWS_AS(schema.choice("c", {}, ""), std::logic_error);
  CHECK_THROWS_AS(schema.integer_list("l", 3, 2, ""), std::logic_error);
}
