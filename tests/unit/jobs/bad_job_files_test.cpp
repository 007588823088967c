// The table of bad job files: tests/bad_jobs/*.yaml, each opening with "# expect: MESSAGE", where MESSAGE
// is the exact error after the file name ("LINE:COL: error: ..."). Validated against the real registry.
#include <catch2/catch_test_macros.hpp>

#include <filesystem>
#include <fstream>
#include <set>

#include "pbrfit/core/error.hpp"
#include "pbrfit/jobs/job_kinds.hpp"

using namespace pbrfit;

namespace {

std::string expected_message(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string first;
  std::getline(in, first);
  const std::string marker = "# expect: ";
  REQUIRE(first.rfind(marker, 0) == 0);
  const std::string rest = first.substr(marker.size());
  // "error: ..." alone means a message without a line and column.
  return file.string() + (rest.rfind("error:", 0) == 0 ? ": " : ":") + rest;
}

std::string rejection(const std::filesystem::path& file) {
  try {
    const auto job = spec::load_job_file(file.string(), jobs::kind_catalogue());
    jobs::make_workload(job);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

}  // namespace

TEST_CASE("every bad job file is rejected with its exact one-line message") {
  const std::filesystem::path dir = std::filesystem::path(PBRFIT_SOURCE_DIR) / "tests" / "bad_jobs";
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.path().extension() == ".yaml") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  REQUIRE(files.size() >= 20);
  for (const auto& file : files) {
    INFO(file.filename().string());
    CHECK(rejection(file) == expected_message(file));
  }
}

// A shipped job may read the result of another shipped job (symbolic regression of a LUT, renders of
// prefiltered tables): before that job has run, the only acceptable refusal is that its result is not there yet.
bool waits_for_shipped_result(const std::string& message, const std::set<std::string>& shipped_outputs) {
  const std::string marker = "' names ";
  const auto at = message.find(marker);
  if (at == std::string::npos) return false;
  const auto start = at + marker.size(), end = message.find(": cannot read file: No such file", start);
  return end != std::string::npos && shipped_outputs.contains(message.substr(start, end - start));
}

TEST_CASE("every shipped job file is valid") {
  const std::filesystem::path dir = std::filesystem::path(PBRFIT_SOURCE_DIR);
  std::set<std::string> outputs;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "jobs"))
    if (entry.path().extension() == ".yaml") outputs.insert(spec::load_job_file(entry.path().string(), jobs::kind_catalogue()).output);
  std::size_t count = 0;
  const auto previous = std::filesystem::current_path();
  std::filesystem::current_path(dir);  // job files name their data relative to the project
  for (const auto* folder : {"jobs", "tests/jobs"}) {
    for (const auto& entry : std::filesystem::directory_iterator(dir / folder)) {
      if (entry.path().extension() != ".yaml") continue;
      INFO(entry.path().string());
      const std::string message = rejection(entry.path());
      CHECK((message == "(accepted)" || waits_for_shipped_result(message, outputs)));
      ++count;
    }
  }
  std::filesystem::current_path(previous);
  CHECK(count >= 6);
}
