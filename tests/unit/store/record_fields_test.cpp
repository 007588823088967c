// Record-field reading (record_fields.hpp) and group listing (result_file.hpp): fields come back whole and
// in row order whatever the other fields, empty tables give empty fields, and every misuse is refused.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <cmath>

#include "pbrfit/core/error.hpp"
#include "pbrfit/store/record_fields.hpp"
#include "pbrfit/store/result_file.hpp"
#include "store_test_paths.hpp"

using namespace pbrfit;
using Catch::Matchers::ContainsSubstring;
using store::ValueType;

namespace {

store::Table member_table(const char* name) {
  return {name, {"member"}, "front members", ValueType::f64,
          {{"expression", ValueType::text, "its text"},
           {"cost", ValueType::f64, "cost"},
           {"operations", ValueType::u32, "live operations"},
           {"knee", ValueType::u8, "1 for the knee"}},
          true};
}

// Group "out" with a front of three members, an empty growing table, a plain table and a nested group.
std::string fields_file() {
  const auto path = temporary_path("record_fields.h5");
  store::Group out;
  out.name = "out";
  out.axes = {{"x", {0, 1}, "x"}};
  out.tables = {member_table("front"), member_table("empty"), {"plain", {"x"}, "numbers"}};
  store::Group inner;
  inner.name = "out/inner";
  store::Group other;
  other.name = "b_other";
  store::RunInfo info;
  info.job_name = "fields";
  info.job_kind = "symreg";
  store::ResultFile file(path, {{out, inner, other}}, info);
  // cost, operations, knee per member; the operations and knees are integers, as their fields are
  const std::vector<store::Number> numbers = {0.5, 1, 0, 1e300, 7, 1, 3.25, std::uint32_t{4294967295}, 0};
  file.write({{"out", "front", {0}, {3}, numbers, {"x * x", "sin(x) + 0.1", "<b>&\"'\n"}},
              {"out", "plain", {0}, {2}, {1, 2}, {}}},
             store::Progress{});
  file.publish();
  return path;
}

}  // namespace

TEST_CASE("a record table's fields read back whole, in row order, each in its kind") {
  const auto path = fields_file();
  CHECK(store::read_text_field(path, "out/front", "expression") ==
        std::vector<std::string>{"x * x", "sin(x) + 0.1", "<b>&\"'\n"});
  CHECK(store::read_number_field(path, "out/front", "cost") == std::vector<double>{0.5, 1e300, 3.25});
  CHECK(store::read_number_field(path, "out/front", "operations") == std::vector<double>{1, 7, 4294967295.0});
  CHECK(store::read_number_field(path, "out/front", "knee") == std::vector<double>{0, 1, 0});
}

TEST_CASE("a record table with no rows yet has empty fields") {
  const auto path = fields_file();
  CHECK(store::read_text_field(path, "out/empty", "expression").empty());
  CHECK(store::read_number_field(path, "out/empty", "cost").empty());
}

TEST_CASE("a missing table or field, a table without records and a field of the other kind are refused") {
  const auto path = fields_file();
  CHECK_THROWS_AS(store::read_text_field(path, "out/none", "expression"), RunError);
  CHECK_THROWS_WITH(store::read_text_field(path, "out/front", "name"),
                    ContainsSubstring("'out/front' has no field 'name'"));
  CHECK_THROWS_WITH(store::read_number_field(path, "out/plain", "cost"),
                    ContainsSubstring("'out/plain' is not a record table"));
  CHECK_THROWS_WITH(store::read_number_field(path, "out/front", "expression"),
                    ContainsSubstring("field 'expression' of 'out/front' is not a number"));
  CHECK_THROWS_WITH(store::read_text_field(path, "out/front", "cost"),
                    ContainsSubstring("field 'cost' of 'out/front' is not a text"));
  CHECK_THROWS_AS(store::read_text_field(temporary_path("absent.h5"), "out/front", "expression"), RunError);
}

TEST_CASE("the groups inside a group are listed by name, without its tables and axes") {
  const auto path = fields_file();
  CHECK(store::read_group_names(path, "") == std::vector<std::string>{"b_other", "out"});
  CHECK(store::read_group_names(path, "out") == std::vector<std::string>{"inner"});
  CHECK(store::read_group_names(path, "out/inner").empty());
  CHECK_THROWS_AS(store::read_group_names(path, "missing"), RunError);
}
