// A checkpoint whose checksum is valid but whose content this job could not have written (ids out of
// range, a stage the job does not have, malformed results) is refused with exit 2 before the result
// file is touched, and is itself kept.
#include <catch2/catch_test_macros.hpp>

#include <csignal>
#include <fstream>
#include <functional>
#include <iterator>

#include "chain_runs.hpp"
#include "pbrfit/core/error.hpp"
#include "pbrfit/store/checkpoint_file.hpp"
#include "pbrfit/store/result_file.hpp"

using namespace pbrfit;
using testing::ChainRun;
using testing::run_chain;
using testing::scratch_path;

namespace {

ChainRun small_chain() {
  ChainRun run;
  run.chain.stages = 2;
  run.chain.items = 8;
  return run;
}

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// An interrupted run (stage 1, three results in), whose checkpoint is then rewritten by `craft`.
void interrupted_then_crafted(const std::string& path, const std::function<void(store::CheckpointState&)>& craft) {
  auto stopped = small_chain();
  stopped.chain.signal = SIGTERM;
  stopped.chain.signal_stage = 1;
  stopped.chain.signal_after = 3;
  REQUIRE(run_chain(stopped, path) == exit_interrupted);
  auto state = store::read_checkpoint(store::checkpoint_path_for(path)).state;
  REQUIRE(state.stage == 1);
  craft(state);
  store::CheckpointFile(store::checkpoint_path_for(path)).write_snapshot(state);
}

}  // namespace

TEST_CASE("a crafted checkpoint is refused before the result file is touched") {
  const std::vector<std::pair<const char*, std::function<void(store::CheckpointState&)>>> crafts = {
      {"an item beyond the stage", [](auto& s) { s.done.push_back(1u << 30); }},
      {"the item one past the last", [](auto& s) { s.done.push_back(8); }},
      {"an item finished twice", [](auto& s) { s.done.push_back(s.done.front()); }},
      {"a stage the job does not have", [](auto& s) { s.stage = 5; }},
      {"a kept result of a later stage", [](auto& s) { s.retained[WorkItemId{4, 0}] = Bytes(16); }},
      {"a malformed kept result", [](auto& s) { s.retained.begin()->second.resize(3); }},
      {"rows of an unfinished item", [](auto& s) { s.appends[7] = Bytes(8); }},
      {"row counts of a table that does not grow", [](auto& s) { s.rows.push_back(1); }},
  };
  for (const auto& [name, craft] : crafts) {
    DYNAMIC_SECTION(name) {
      const auto path = scratch_path("crafted.h5");
      interrupted_then_crafted(path, craft);
      const std::string result_before = file_bytes(path);
      const std::string checkpoint_before = file_bytes(store::checkpoint_path_for(path));
      auto resumed = small_chain();
      resumed.resume = true;
      CHECK(run_chain(resumed, path) == exit_invalid_input);
      CHECK(file_bytes(path) == result_before);
      CHECK(file_bytes(store::checkpoint_path_for(path)) == checkpoint_before);
    }
  }
}

TEST_CASE("the untouched checkpoint of an interrupted run still resumes") {
  const auto path = scratch_path("uncrafted.h5");
  interrupted_then_crafted(path, [](auto&) {});
  auto resumed = small_chain();
  resumed.resume = true;
  REQUIRE(run_chain(resumed, path) == exit_success);
  CHECK(store::read_result_summary(path).state == store::RunStatus::complete);
}
