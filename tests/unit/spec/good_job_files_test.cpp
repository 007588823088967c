// Valid job files: defaults filled in, values read back, positions recorded.
#include <catch2/catch_test_macros.hpp>
#include <catch2/generators/catch_generators.hpp>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "pbrfit/spec/job_spec.hpp"
#include "test_kinds.hpp"

namespace {

using pbrfit::SourcePosition;
using pbrfit::spec::JobSpec;
using pbrfit::spec::parse_job_text;
using pbrfit::spec::Section;
using pbrfit::spec::testing::test_kinds;

JobSpec parse(const std::string& text) { return parse_job_text(text, "test.yaml", test_kinds()); }

void check_at(const SourcePosition& where, int line, int column) {
  CHECK(where.file == "test.yaml");
  CHECK(where.line == line);
  CHECK(where.column == column);
}

const std::string minimal_job = R"(name: dfg
kind: lut
lut:
  function: dfg
)";

const std::string complete_job = R"(# Every key written out.
name: dfg-full_2.x
kind: lut
seed: 42
output: out/dfg.h5
checkpoint:
  interval_seconds: 12.5
  interval_items: 100
resources:
  ranks: 8
  time_limit: 1-02:03:04
  partition: gpu
  account: "render"
lut:
  function: directional_albedo
  resolution: [64, 128]
  moments: [0, 1, 2]
  tolerance: 1e-8
  max_evaluations: 5000
  importance_sampling: no
  visibility: separable_schlick
  label: "first try"
  n_dot_v: {samples: 16, max: 0.5}
  roughness:
    min: 0.05
)";

}  // namespace

TEST_CASE("a minimal job gets every default") {
  const JobSpec spec = parse(minimal_job);
  CHECK(spec.file == "test.yaml");
  CHECK(spec.text == minimal_job);
  CHECK(spec.name == "dfg");
  CHECK(spec.kind == "lut");
  CHECK(spec.seed == 0);
  CHECK(spec.output == "results/dfg.h5");
  CHECK(spec.checkpoint.interval_seconds == 30.0);
  CHECK(spec.checkpoint.interval_items == 0);
  CHECK(spec.resources.ranks == 2);
  CHECK(spec.resources.time_limit == "01:00:00");
  CHECK(spec.resources.time_limit_seconds == 3600.0);
  CHECK(spec.resources.partition.empty());
  CHECK(spec.resources.account.empty());

  const Section& lut = spec.kind_section;
  CHECK(lut.get_string("function") == "dfg");
  CHECK(lut.given("function"));
  CHECK(lut.get_int_list("resolution") == std::vector<std::int64_t>{32, 32});
  CHECK(lut.get_int_list("moments") == std::vector<std::int64_t>{0});
  CHECK(lut.get_number("tolerance") == 1e-6);
  CHECK(lut.get_int("max_evaluations") == 100000);
  CHECK(lut.get_bool("importance_sampling"));
  CHECK(lut.get_string("visibility") == "height_correlated");
  CHECK_FALSE(lut.given("tolerance"));
  CHECK(lut.has("tolerance"));
}

TEST_CASE("absent optional keys: defaulted sections, and keys without a default") {
  const Section& lut = parse(minimal_job).kind_section;
  CHECK_FALSE(lut.has("label"));          // no default
  CHECK_FALSE(lut.has("n_dot_v"));        // has a required key, so it cannot be defaulted
  CHECK_THROWS_AS(lut.get_string("label"), std::logic_error);
  CHECK_THROWS_AS(lut.get_section("n_dot_v"), std::logic_error);
  REQUIRE(lut.has("roughness"));
  CHECK_FALSE(lut.given("roughness"));
  const Section& roughness = lut.get_section("roughness");
  CHECK(roughness.get_number("min") == 0.01);
  CHECK(roughness.get_number("max") == 1.0);
  check_at(roughness.position("min"), 4, 3);  // a defaulted section stands where its parent does
}

TEST_CASE("defaulted keys are positioned at their section") {
  const JobSpec spec = parse(minimal_job);
  check_at(spec.kind_section.position(), 4, 3);
  check_at(spec.kind_section.position("tolerance"), 4, 3);
  check_at(spec.kind_section.position("label"), 4, 3);
  check_at(spec.kind_section.position("function"), 4, 13);
}

TEST_CASE("a complete job reads back every value with its position") {
  const JobSpec spec = parse(complete_job);
  CHECK(spec.text == complete_job);
  CHECK(spec.name == "dfg-full_2.x");
  CHECK(spec.seed == 42);
  CHECK(spec.output == "out/dfg.h5");
  CHECK(spec.checkpoint.interval_seconds == 12.5);
  CHECK(spec.checkpoint.interval_items == 100);
  CHECK(spec.resources.ranks == 8);
  CHECK(spec.resources.time_limit == "1-02:03:04");
  CHECK(spec.resources.time_limit_seconds == 93784.0);
  CHECK(spec.resources.partition == "gpu");
  CHECK(spec.resources.account == "render");

  const Section& lut = spec.kind_section;
  check_at(lut.position(), 15, 3);
  CHECK(lut.get_string("function") == "directional_albedo");
  CHECK(lut.get_int_list("resolution") == std::vector<std::int64_t>{64, 128});
  check_at(lut.position("resolution"), 16, 15);
  CHECK(lut.get_int_list("moments") == std::vector<std::int64_t>{0, 1, 2});
  CHECK(lut.get_number("tolerance") == 1e-8);
  check_at(lut.position("tolerance"), 18, 14);
  CHECK(lut.get_int("max_evaluations") == 5000);
  CHECK_FALSE(lut.get_bool("importance_sampling"));
  CHECK(lut.get_string("visibility") == "separable_schlick");
  CHECK(lut.get_string("label") == "first try");
  check_at(lut.position("label"), 22, 10);

  REQUIRE(lut.has("n_dot_v"));
  CHECK(lut.given("n_dot_v"));
  const Section& n_dot_v = lut.get_section("n_dot_v");
  check_at(lut.position("n_dot_v"), 23, 12);
  check_at(n_dot_v.position(), 23, 12);
  CHECK(n_dot_v.get_int("samples") == 16);
  CHECK(n_dot_v.get_number("max") == 0.5);
  CHECK(n_dot_v.get_number("min") == 0.0);
  CHECK_FALSE(n_dot_v.given("min"));
  check_at(n_dot_v.position("max"), 23, 31);

  const Section& roughness = lut.get_section("roughness");
  CHECK(lut.given("roughness"));
  CHECK(roughness.get_number("min") == 0.05);
  CHECK(roughness.get_number("max") == 1.0);
  check_at(roughness.position("min"), 25, 10);
  check_at(roughness.position("max"), 25, 5);
}

TEST_CASE("cross-field checks done later by a kind report at the key's value") {
  const JobSpec spec = parse(complete_job);
  try {
    spec.kind_section.reject("tolerance", "must not be below 1e-6 for a 64x128 table");
    FAIL("no throw");
  } catch (const pbrfit::InputError& error) {
    CHECK(std::string(error.what()) ==
          "test.yaml:18:14: error: 'tolerance' must not be below 1e-6 for a 64x128 table");
  }
}

TEST_CASE("time limits in every Slurm form") {
  const auto [written, seconds] = GENERATE(table<std::string, double>({
      {"30", 1800.0},
      {"05:00", 300.0},
      {"5:30", 330.0},
      {"01:00:00", 3600.0},
      {"48:00:00", 172800.0},
      {"1-02:03:04", 93784.0},
      {"2-12", 216000.0},
      {"0-00:30", 1800.0},
  }));
  INFO(written);
  const JobSpec spec = parse("name: dfg\nkind: lut\nresources: {time_limit: \"" + written +
                             "\"}\nlut: {function: dfg}\n");
  CHECK(spec.resources.time_limit == written);
  CHECK(spec.resources.time_limit_seconds == seconds);
}

TEST_CASE("scalars are typed by what they say, not how they are quoted") {
  const JobSpec spec = parse(R"(name: 2024
kind: "lut"
seed: "5"
resources: {ranks: +4, time_limit: 10:00}
lut:
  function: 'dfg'
  tolerance: 3
  importance_sampling: off
  label: 12
)");
  CHECK(spec.name == "2024");
  CHECK(spec.seed == 5);
  CHECK(spec.resources.ranks == 4);
  CHECK(spec.resources.time_limit_seconds == 600.0);
  CHECK(spec.kind_section.get_number("tolerance") == 3.0);
  CHECK_THROWS_AS(spec.kind_section.get_int("tolerance"), std::logic_error);  // a number field
  CHECK_FALSE(spec.kind_section.get_bool("importance_sampling"));
  CHECK(spec.kind_section.get_string("label") == "12");
}

TEST_CASE("booleans accept what yaml-cpp accepts") {
  const auto [written, value] = GENERATE(table<std::string, bool>({
      {"true", true}, {"True", true}, {"yes", true}, {"on", true}, {"y", true},
      {"false", false}, {"FALSE", false}, {"no", false}, {"Off", false}, {"n", false},
  }));
  INFO(written);
  const JobSpec spec =
      parse("name: dfg\nkind: lut\nlut: {function: dfg, importance_sampling: " + written + "}\n");
  CHECK(spec.kind_section.get_bool("importance_sampling") == value);
}

TEST_CASE("comments, anchors, CRLF line ends and a byte-order mark are fine") {
  const std::string text =
      "\xEF\xBB\xBF# job\r\nname: &n dfg\r\nkind: lut\r\nlut:\r\n  function: *n\r\n  tolerance: 1e-3\r\n";
  const JobSpec spec = parse(text);
  CHECK(spec.text == text);
  CHECK(spec.kind_section.get_string("function") == "dfg");
  check_at(spec.kind_section.position("tolerance"), 6, 14);
}

TEST_CASE("the common schema declares the common keys in order") {
  std::vector<std::string> names;
  for (const auto& field : pbrfit::spec::common_schema().fields()) names.push_back(field.name);
  CHECK(names == std::vector<std::string>{"name", "kind", "seed", "output", "checkpoint", "resources"});
  const auto* resources = pbrfit::spec::common_schema().find("resources");
  REQUIRE(resources);
  REQUIRE(resources->nested);
  const auto* ranks = resources->nested->find("ranks");
  REQUIRE(ranks);
  CHECK(*ranks->min == 1);
  CHECK(*ranks->max == 65536);
}
