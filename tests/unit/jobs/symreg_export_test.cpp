// `pbrfit export`'s symreg side: a result written from a real (tiny) symbolic-regression run is read back,
// its knee or any member parsed and exported with the output's inputs as parameters, and every refusal is
// an InputError naming the file or the option.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <filesystem>
#include <limits>
#include <string>

#include <unistd.h>

#include "pbrfit/core/error.hpp"
#include "pbrfit/jobs/job_kinds.hpp"
#include "pbrfit/jobs/symreg/member_export.hpp"
#include "pbrfit/jobs/symreg/result_front.hpp"
#include "pbrfit/jobs/symreg/symreg_kind.hpp"
#include "pbrfit/jobs/symreg/symreg_workload.hpp"
#include "pbrfit/store/result_file.hpp"

using namespace pbrfit;
using namespace pbrfit::jobs::symreg;
using Catch::Matchers::ContainsSubstring;
using Catch::Matchers::StartsWith;

namespace {

const char* job_text = R"(name: tiny-symreg
kind: symreg
symreg:
  dataset: {generator: nguyen5, points: 20}
  operators: [add, sub, mul, sin, cos]
  islands: 2
  population: 30
  generations: 4
  migration_interval: 2
  migrants: 1
  anchors: [{name: exact, expression: "sin(x*x) * cos(x) - 1"}]
)";

// One directory per process, removed when it ends: ctest -j runs this file's test cases side by side,
// each writing the same names.
struct ScratchDirectory {
  std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("pbrfit-jobs-tests-" + std::to_string(::getpid()));
  ~ScratchDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};

std::string result_path(const char* name) {
  static const ScratchDirectory scratch;
  std::filesystem::create_directories(scratch.path);
  return (scratch.path / name).string();
}

// Runs every stage in process; the file gets the last stage's blocks (fronts, anchors, predictions) only
// when `finished`.
std::string symreg_result(const char* name, bool finished, const std::string& text = job_text) {
  const auto job = spec::parse_job_text(text, "tiny.yaml", jobs::kind_catalogue());
  const SymregWorkload w(symreg_settings(job.kind_section));
  ItemResults kept;
  std::vector<store::Block> final_blocks;
  for (std::uint32_t s = 0; s < w.stage_count(); ++s) {
    for (std::uint64_t i = 0; i < w.item_count(s); ++i) {
      const Bytes context, input = w.item_input(s, i, kept);
      kept[{s, i}] = w.compute(runtime::ItemTask{{s, i}, context, input, 7});
      if (s + 1 == w.stage_count()) final_blocks = w.blocks({s, i}, kept[{s, i}]);
    }
  }
  const auto path = result_path(name);
  store::RunInfo info;
  info.job_name = "tiny-symreg";
  info.job_kind = "symreg";
  info.job_yaml = text;
  store::ResultFile file(path, w.layout(), info);
  store::Progress progress;
  progress.state = finished ? store::RunStatus::complete : store::RunStatus::running;
  file.write(finished ? final_blocks : std::vector<store::Block>{}, progress);
  file.publish();
  return path;
}

std::string exported(const std::string& path, const MemberExport& request) {
  return export_member(path, store::read_result_summary(path), request);
}

}  // namespace

TEST_CASE("the knee is the default member; its function takes the output's inputs and says what it is") {
  const auto path = symreg_result("finished.h5", true);
  const OutputFront front = read_output_front(path, "y");
  REQUIRE(front.inputs == std::vector<std::string>{"x"});
  REQUIRE(front.members.size() >= 2);
  std::size_t knee = 0;
  while (!front.members[knee].knee) ++knee;
  const std::string text = exported(path, {});
  CHECK_THAT(text, StartsWith("// tiny-symreg, output y, member " + std::to_string(knee) + " of " +
                              std::to_string(front.members.size()) + " (the knee): cost "));
  CHECK_THAT(text, ContainsSubstring("\nfloat y(float x) {\n"));
  CHECK(text.find("#include") == std::string::npos);
}

TEST_CASE("any member exports in each language, under the name asked for") {
  const auto path = symreg_result("finished.h5", true);
  MemberExport request;
  request.member = 0;
  request.language = gp::ExportLanguage::cpp;
  request.cpp_double = true;
  request.function_name = "cheapest";
  const std::string text = exported(path, request);
  CHECK_THAT(text, StartsWith("// tiny-symreg, output y, member 0 of "));
  CHECK_THAT(text, ContainsSubstring("\n#include <cmath>\n\ninline double cheapest(double x) {\n"));
  request.language = gp::ExportLanguage::glsl;
  request.cpp_double = false;
  CHECK_THAT(exported(path, request), ContainsSubstring("\nfloat cheapest(float x) {\n"));
}

TEST_CASE("export refuses, on one line naming the file or option, what it cannot export") {
  const auto path = symreg_result("finished.h5", true);
  const auto refusal = [&](const MemberExport& request) {
    try {
      exported(path, request);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no refusal");
  };
  MemberExport request;
  request.output = "z";
  CHECK(refusal(request) == path + ": error: no output 'z' in the result; its outputs: 'y'");
  request = {};
  request.member = 1000;
  CHECK_THAT(refusal(request), StartsWith(path + ": error: member 1000 is out of range: the front of 'y' has "));
  request = {};
  request.function_name = "sin";
  CHECK_THAT(refusal(request), StartsWith("--name: error: 'sin' is not a name every export language accepts"));
  request = {};
  request.cpp_double = true;
  CHECK(refusal(request) == "--double: error: only C++ exports can use double (--format cpp)");

  const auto running = symreg_result("running.h5", false);
  REQUIRE_THROWS_WITH(exported(running, {}),
                      running + ": error: no front of 'y' yet: the job has not finished its last stage (running, 0 of "
                                "0 work items done)");
  auto not_symreg = store::read_result_summary(path);
  not_symreg.job_kind = "lut";
  REQUIRE_THROWS_WITH(export_member(path, not_symreg, {}),
                      path + ": error: not a symbolic-regression or genBRDF result (job kind 'lut'); export reads "
                             "the fronts of symreg and brdf_search results");
}

// --member test: the validation error chooses (issue 24); without test rows it is refused, naming the file.
TEST_CASE("the member of the lowest test error is chosen on request, and refused without test rows") {
  // (In this tiny run the knee is also the best on the test rows; the choice itself is tested below.)
  const auto path = symreg_result("by-test.h5", true);
  const auto front = read_output_front(path, "y");
  const std::size_t best = lowest_test_error_member(front).value();
  MemberExport request;
  request.by_test_error = true;
  CHECK_THAT(exported(path, request), StartsWith("// tiny-symreg, output y, member " + std::to_string(best) + " of "));
  std::string untested = job_text;
  untested.replace(untested.find("points: 20}"), 11, "points: 20, test_points: 0}");
  const auto no_test = symreg_result("no-test.h5", true, untested);
  CHECK_THROWS_WITH(exported(no_test, request),
                    no_test + ": error: the front of 'y' has no test errors (no test rows: see "
                              "dataset.test_fraction); choose with --member");
}

TEST_CASE("the lowest test error: NaN members skipped, the cheapest of equals, none without test errors") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  OutputFront front{"y", {"x"}, {}};
  for (const double test : {nan, 0.5, 0.2, 0.2, 0.9}) front.members.push_back({"x", 1.0, 0.1, 0.1, test, false});
  front.members[4].knee = true;
  CHECK(lowest_test_error_member(front) == std::optional<std::size_t>(2));
  for (auto& m : front.members) m.test_rmse = nan;
  CHECK_FALSE(lowest_test_error_member(front).has_value());
}
