// spec/keys.hpp: a key declared once fills its member (converted), its optional (only when written), its
// Written (value and whether written) or its callable; choices fill their bound values, sections and lists
// of sections their nested settings; the keys a file writes are listed in the schema's order; checks
// refuse the job at their key; a check naming no key is a bug.
#include <catch2/catch_test_macros.hpp>

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "pbrfit/spec/job_spec.hpp"
#include "pbrfit/spec/keys.hpp"

using namespace pbrfit;

namespace {

enum class Mode { fast, exact };

struct Range {
  double low = 0.0, high = 0.0;
};

struct Demo {
  std::size_t count = 0;
  float ratio = 0.0f;
  Mode mode = Mode::fast;
  std::optional<std::string> label;
  spec::Written<bool> flag;
  std::vector<std::uint32_t> sizes;
  int doubled = 0;
  Range range;
  std::vector<Range> ranges;
  std::string loaded;
  std::vector<spec::WrittenKey> written;
};

spec::Keys<Range> range_keys() {
  spec::Keys<Range> k("range");
  k.number("low", "Lowest.", &Range::low).defaults_to(0.0);
  k.number("high", "Highest.", &Range::high).defaults_to(1.0);
  k.check("high", [](Range& r) -> std::string { return r.high < r.low ? "must be at least 'low'" : ""; });
  return k;
}

spec::Keys<Demo> demo_keys() {
  spec::Keys<Demo> k("demo");
  k.integer("count", "A count.", &Demo::count).defaults_to(std::int64_t{3});
  k.number("ratio", "A ratio.", &Demo::ratio).defaults_to(0.5);
  k.choice<Mode>("mode", {{"fast", Mode::fast}, {"exact", Mode::exact}}, "A mode.", &Demo::mode)
      .defaults_to(std::string("fast"));
  k.string("label", "Free text, no default.", &Demo::label);
  k.boolean("flag", "A flag.", &Demo::flag).defaults_to(true);
  k.integer_list("sizes", 0, 4, "Sizes.", &Demo::sizes).defaults_to(std::vector<std::int64_t>{});
  k.integer("half", "Half of doubled.", [](Demo& d, std::int64_t half) { d.doubled = int(2 * half); })
      .defaults_to(std::int64_t{1});
  k.section("range", range_keys(), "A range.", &Demo::range);
  k.section_list("ranges", range_keys(), 0, 3, "Ranges.", &Demo::ranges);
  k.string("file", "What to load.", [](Demo& d, const std::string& name) { d.loaded = name; }).defaults_to(std::string("a"));
  k.check("file", [](Demo& d) -> std::string {
    if (d.loaded == "missing") return "names a file that does not exist";
    d.loaded = "contents of " + d.loaded;
    return "";
  });
  // A problem found inside what a key names, reported at the key's position by the check itself.
  k.check("label", [](Demo& d, const SourcePosition& where) -> std::string {
    if (d.label == std::optional<std::string>("bad column")) throw InputError(where, "the file has no such column");
    return "";
  });
  k.list_written(&Demo::written);
  return k;
}

spec::KindCatalogue catalogue(const spec::Schema& schema) {
  return {{"demo"}, [&schema](const std::string&) -> const spec::Schema& { return schema; }};
}

Demo read(const std::string& section_text) {
  const auto keys = demo_keys();
  const auto job = spec::parse_job_text("name: t\nkind: demo\ndemo:\n" + section_text, "job.yaml",
                                        catalogue(keys.schema()));
  return keys.read(job.kind_section);
}

std::string refusal(const std::string& section_text) {
  try {
    read(section_text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

}  // namespace

TEST_CASE("keys left out fill their defaults, and optional keys without one fill nothing") {
  const Demo d = read("  mode: fast\n");
  CHECK(d.count == 3);
  CHECK(d.ratio == 0.5f);
  CHECK(d.mode == Mode::fast);
  CHECK_FALSE(d.label.has_value());
  CHECK(d.flag.value);
  CHECK_FALSE(d.flag.written);
  CHECK(d.sizes.empty());
  CHECK(d.doubled == 2);
  CHECK((d.range.low == 0.0 && d.range.high == 1.0));
  CHECK(d.ranges.empty());
  CHECK(d.loaded == "contents of a");
  REQUIRE(d.written.size() == 1);  // defaults are not written
  CHECK(d.written[0].key == "mode");
}

TEST_CASE("written keys fill their members, converted, and their callables") {
  const Demo d = read(
      "  count: 7\n  ratio: 2\n  mode: exact\n  label: hello\n  flag: true\n  sizes: [4, 8]\n  half: 5\n"
      "  range: {low: 0.25, high: 0.75}\n  ranges: [{low: 1, high: 2}, {high: 3}]\n  file: b\n");
  CHECK(d.count == 7);
  CHECK(d.ratio == 2.0f);
  CHECK(d.mode == Mode::exact);
  CHECK(d.label == std::optional<std::string>("hello"));
  CHECK((d.flag.value && d.flag.written));
  CHECK(d.sizes == std::vector<std::uint32_t>{4, 8});
  CHECK(d.doubled == 10);
  CHECK((d.range.low == 0.25 && d.range.high == 0.75));
  REQUIRE(d.ranges.size() == 2);
  CHECK((d.ranges[0].low == 1.0 && d.ranges[0].high == 2.0));
  CHECK((d.ranges[1].low == 0.0 && d.ranges[1].high == 3.0));
  CHECK(d.loaded == "contents of b");
  std::vector<std::string> written;
  for (const auto& w : d.written) written.push_back(w.key);
  CHECK(written == std::vector<std::string>{"count", "ratio", "mode", "label", "flag", "sizes", "half", "range",
                                            "ranges", "file"});  // in the schema's order
  std::string refused;
  try {
    d.written[1].reject("is refused");
  } catch (const InputError& e) {
    refused = e.what();
  }
  CHECK(refused == "job.yaml:5:10: error: 'ratio' is refused");
}

TEST_CASE("a check refuses the job at its key, nested checks at theirs") {
  CHECK(refusal("  file: missing\n") == "job.yaml:4:9: error: 'file' names a file that does not exist");
  CHECK(refusal("  range: {low: 2, high: 1}\n") == "job.yaml:4:25: error: 'high' must be at least 'low'");
  CHECK(refusal("  ranges: [{low: 5}]\n") == "job.yaml:4:12: error: 'high' must be at least 'low'");  // defaulted: the mapping's position
}

TEST_CASE("a check may report at its key's position itself") {
  CHECK(refusal("  label: bad column\n") == "job.yaml:4:10: error: the file has no such column");
}

TEST_CASE("a check naming no key of the schema is refused when it is declared") {
  spec::Keys<Range> k("range");
  k.number("low", "Lowest.", &Range::low);
  CHECK_THROWS_AS(k.check("lowest", [](Range&) { return std::string(); }), std::logic_error);
  CHECK_THROWS_AS(k.number("low", "Twice.", &Range::high), std::logic_error);
}
