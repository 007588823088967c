// load_job_file: reading from disk, and the failures that happen before any YAML is seen.
#include <catch2/catch_test_macros.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

#include "pbrfit/core/error.hpp"
#include "pbrfit/spec/job_spec.hpp"
#include "test_kinds.hpp"

namespace {

namespace fs = std::filesystem;
using pbrfit::InputError;
using pbrfit::spec::load_job_file;
using pbrfit::spec::parse_job_text;
using pbrfit::spec::testing::test_kinds;

// A fresh directory for this process, removed at the end of the test.
struct ScratchDirectory {
  fs::path path = fs::temp_directory_path() / ("pbrfit-spec-test-" + std::to_string(::getpid()));
  ScratchDirectory() { fs::create_directories(path); }
  ~ScratchDirectory() { fs::remove_all(path); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path / name, std::ios::binary) << text;
    return (path / name).string();
  }
};

std::string rejection(const auto& load) {
  try {
    load();
  } catch (const InputError& error) {
    return error.what();
  }
  return "accepted";
}

}  // namespace

TEST_CASE("a job file is loaded byte for byte, under the path as given") {
  const ScratchDirectory scratch;
  const std::string text = "name: dfg   # trailing comment\nkind: lut\nlut: {function: dfg}\n\n";
  const std::string path = scratch.write("dfg.yaml", text);
  const auto spec = load_job_file(path, test_kinds());
  CHECK(spec.file == path);
  CHECK(spec.text == text);
  CHECK(spec.name == "dfg");
}

TEST_CASE("an unreadable job file") {
  const ScratchDirectory scratch;
  const std::string missing = (scratch.path / "missing.yaml").string();
  CHECK(rejection([&] { load_job_file(missing, test_kinds()); }) ==
        missing + ": error: cannot read job file: No such file or directory");
  const std::string directory = scratch.path.string();
  CHECK(rejection([&] { load_job_file(directory, test_kinds()); }) ==
        directory + ": error: is a directory, not a job file");
}

TEST_CASE("only regular job files of bounded size are read") {
  const ScratchDirectory scratch;
  const std::string fifo = (scratch.path / "fifo.yaml").string();
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  CHECK(rejection([&] { load_job_file(fifo, test_kinds()); }) == fifo + ": error: is not a regular file");
  CHECK(rejection([&] { load_job_file("/dev/zero", test_kinds()); }) == "/dev/zero: error: is not a regular file");
  const std::string big = scratch.write("big.yaml", "name: dfg\nkind: lut\n" + std::string(300 << 10, '#'));
  CHECK(rejection([&] { load_job_file(big, test_kinds()); }) ==
        big + ": error: is larger than 256 KiB, the most a job file may hold");
  const std::string head = "name: dfg\nkind: lut\nlut: {function: dfg}\n#";
  const std::string at_limit =
      scratch.write("limit.yaml", head + std::string(pbrfit::spec::max_job_file_bytes - head.size(), 'x'));
  CHECK(load_job_file(at_limit, test_kinds()).text.size() == pbrfit::spec::max_job_file_bytes);
}

TEST_CASE("an empty job file") {
  const ScratchDirectory scratch;
  const std::string path = scratch.write("empty.yaml", "");
  CHECK(rejection([&] { load_job_file(path, test_kinds()); }) == path + ": error: the job file is empty");
  for (const std::string text : {"", "   \n\t\n", "# only a comment\n\n# another\n", "---\n", "--- # c\n...\n"}) {
    INFO("'" << text << "'");
    CHECK(rejection([&] { parse_job_text(text, "e.yaml", test_kinds()); }) ==
          "e.yaml: error: the job file is empty");
  }
}
