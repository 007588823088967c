// Lists in job files: of numbers, of names (free or from a set) and of mappings, with their element
// checks, defaults and FILE:LINE:COL messages.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <string>
#include <vector>

#include "pbrfit/spec/job_spec.hpp"
#include "test_kinds.hpp"

namespace {

using Catch::Matchers::Equals;
using pbrfit::InputError;
using pbrfit::spec::JobSpec;
using pbrfit::spec::parse_job_text;
using pbrfit::spec::testing::test_kinds;

JobSpec parse_sweep(const std::string& body) {
  return parse_job_text("name: s\nkind: sweep\nsweep:\n" + body, "s.yaml", test_kinds());
}

std::string message_of(const std::string& body) {
  try {
    parse_sweep(body);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

}  // namespace

TEST_CASE("lists of mappings are validated item by item and keep their order") {
  const JobSpec job = parse_sweep(
      "  axes:\n    - {name: roughness, count: 16}\n    - name: n_dot_v\n  levels: [{name: coarse}]\n");
  const auto& axes = job.kind_section.get_section_list("axes");
  REQUIRE(axes.size() == 2);
  CHECK(axes[0].get_string("name") == "roughness");
  CHECK(axes[0].get_int("count") == 16);
  CHECK(axes[1].get_string("name") == "n_dot_v");
  CHECK(axes[1].get_int("count") == 8);  // defaulted inside the item
  CHECK(axes[1].position().line == 6);
  CHECK(job.kind_section.given("axes"));
}

TEST_CASE("an absent list of mappings is empty when it may be, missing when it must have items") {
  const JobSpec job = parse_sweep("  levels: [{name: only}]\n");
  CHECK(job.kind_section.get_section_list("axes").empty());
  CHECK_FALSE(job.kind_section.given("axes"));
  CHECK_THAT(message_of("  steps: 2\n"), Equals("s.yaml:4:3: error: missing required key 'levels' in 'sweep'"));
}

TEST_CASE("a bad item of a list of mappings is reported inside the item, with its index") {
  CHECK_THAT(message_of("  levels: [{name: a}]\n  axes:\n    - {name: a}\n    - {count: 3}\n"),
             Equals("s.yaml:7:7: error: missing required key 'name' in 'sweep.axes[2]'"));
  CHECK_THAT(message_of("  levels: [{name: a}]\n  axes:\n    - {name: a, cuont: 3}\n"),
             Equals("s.yaml:6:17: error: unknown key 'cuont' in 'sweep.axes[1]'; did you mean 'count'?"));
  CHECK_THAT(message_of("  levels: [{name: a}]\n  axes: [3]\n"),
             Equals("s.yaml:5:10: error: 'sweep.axes[1]' must be a mapping, got '3'"));
  CHECK_THAT(message_of("  levels: []\n"),
             Equals("s.yaml:4:11: error: 'levels' must be a list of at least 1 mapping, got an empty list"));
  CHECK_THAT(message_of("  levels: [{name: a}]\n  axes: [{name: a}, {name: b}, {name: c}, {name: d}, {name: e}]\n"),
             Equals("s.yaml:5:9: error: 'axes' must be a list of 0 to 4 mappings, got a list of 5 items"));
}

TEST_CASE("lists of numbers accept integers and check every element's range") {
  const JobSpec job = parse_sweep("  levels: [{name: a}]\n  weights: [1, 2.5, 1e-3]\n");
  CHECK(job.kind_section.get_number_list("weights") == std::vector<double>{1.0, 2.5, 1e-3});
  CHECK(parse_sweep("  levels: [{name: a}]\n").kind_section.get_number_list("weights") == std::vector<double>{1.0});
  CHECK_THAT(message_of("  levels: [{name: a}]\n  weights: [1, 20]\n"),
             Equals("s.yaml:5:16: error: 'weights' item 2 must be between 0 and 10, got 20"));
  CHECK_THAT(message_of("  levels: [{name: a}]\n  weights: [1, x]\n"),
             Equals("s.yaml:5:16: error: 'weights' item 2 must be a number, got 'x'"));
}

TEST_CASE("lists of names are checked against their set, with a suggestion") {
  const JobSpec job = parse_sweep("  levels: [{name: a}]\n  operators: [add, sin]\n  tags: [x, y]\n");
  CHECK(job.kind_section.get_string_list("operators") == std::vector<std::string>{"add", "sin"});
  CHECK(job.kind_section.get_string_list("tags") == std::vector<std::string>{"x", "y"});
  CHECK_THAT(message_of("  levels: [{name: a}]\n  operators: [add, sinn]\n"),
             Equals("s.yaml:5:20: error: 'operators' item 2 must be one of add, mul, sin; got 'sinn'; "
                    "did you mean 'sin'?"));
  CHECK_THAT(message_of("  levels: [{name: a}]\n  tags: [x, '']\n"),
             Equals("s.yaml:5:13: error: 'tags' item 2 must be a non-empty string, got ''"));
  CHECK_THAT(message_of("  levels: [{name: a}]\n  operators: add\n"),
             Equals("s.yaml:5:14: error: 'operators' must be a list of at least 1 name from add, mul, sin, got "
                    "'add'"));
}
