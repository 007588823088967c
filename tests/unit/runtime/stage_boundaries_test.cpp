#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <csignal>
#include <filesystem>
#include <set>

#include "chain_runs.hpp"
#include "pbrfit/core/error.hpp"
#include "pbrfit/store/checkpoint_file.hpp"
#include "pbrfit/store/result_file.hpp"

using namespace pbrfit;
using testing::ChainRun;
using testing::run_chain;
using testing::scratch_path;

namespace {

ChainRun uneven(int threads) {
  ChainRun run;
  run.chain.stages = 3;
  run.chain.items = 12;
  run.chain.spin_microseconds = 300;  // items cost 0 to 1.2 ms: the last result of a stage comes late
  run.threads = threads;
  return run;
}

std::vector<double> table(const std::string& path, const std::string& name) { return store::read_table(path, name); }

// Equal values in equal places, unwritten (NaN) entries included.
bool same_numbers(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!(a[i] == b[i] || (std::isnan(a[i]) && std::isnan(b[i])))) return false;
  return true;
}

}  // namespace

TEST_CASE("each stage starts from every result of the stage before, whatever the thread count") {
  const auto reference = scratch_path("boundaries-1.h5");
  REQUIRE(run_chain(uneven(1), reference) == exit_success);
  for (int threads : {2, 3, 4}) {
    const auto other = scratch_path("boundaries-" + std::to_string(threads) + ".h5");
    REQUIRE(run_chain(uneven(threads), other) == exit_success);
    CHECK(table(other, "chain/value") == table(reference, "chain/value"));
    CHECK(table(other, "chain/random") == table(reference, "chain/random"));
  }
  CHECK(store::read_result_summary(reference).state == store::RunStatus::complete);
  CHECK_FALSE(std::filesystem::exists(store::checkpoint_path_for(reference)));
  CHECK_FALSE(std::filesystem::exists(store::journal_path_for(reference)));
}

TEST_CASE("two stages of one item never draw the same random numbers") {
  const auto path = scratch_path("streams.h5");
  REQUIRE(run_chain(uneven(2), path) == exit_success);
  const auto random = table(path, "chain/random");
  CHECK(std::set<double>(random.begin(), random.end()).size() == random.size());
}

TEST_CASE("a stop at every stage boundary and in the middle of every stage resumes to the same numbers") {
  const auto reference = scratch_path("stops-reference.h5");
  REQUIRE(run_chain(uneven(2), reference) == exit_success);
  for (std::uint32_t stage = 0; stage < 3; ++stage) {
    for (std::uint64_t after : {std::uint64_t{0}, std::uint64_t{5}}) {
      if (stage == 0 && after == 0) continue;  // before any work: nothing to resume
      DYNAMIC_SECTION("stage " << stage << " after " << after << " results") {
        const auto path = scratch_path("stops.h5");
        auto stopped = uneven(2);
        stopped.chain.signal = SIGTERM;
        stopped.chain.signal_stage = stage;
        stopped.chain.signal_after = after;
        REQUIRE(run_chain(stopped, path) == exit_interrupted);
        CHECK(store::read_result_summary(path).state == store::RunStatus::interrupted);
        auto resumed = uneven(1);
        resumed.resume = true;
        REQUIRE(run_chain(resumed, path) == exit_success);
        CHECK(table(path, "chain/value") == table(reference, "chain/value"));
        CHECK(table(path, "chain/random") == table(reference, "chain/random"));
      }
    }
  }
}

TEST_CASE("a workload may skip stages: their items count as done, and a stop across the skip resumes the same") {
  auto skipping = uneven(2);
  skipping.chain.stages = 5;
  skipping.chain.skip_after = 1;
  skipping.chain.skip_to = 4;  // stages 2 and 3 never run
  const auto reference = scratch_path("skip-reference.h5");
  REQUIRE(run_chain(skipping, reference) == exit_success);
  const auto summary = store::read_result_summary(reference);
  CHECK(summary.items_done == summary.items_total);
  const auto values = table(reference, "chain/value");  // [stage][item]: skipped stages stay unwritten
  for (std::size_t item = 0; item < 12; ++item) {
    CHECK(std::isnan(values[2 * 12 + item]));
    CHECK(std::isnan(values[3 * 12 + item]));
    CHECK_FALSE(std::isnan(values[4 * 12 + item]));
  }
  for (std::uint64_t after : {std::uint64_t{0}, std::uint64_t{5}}) {
    DYNAMIC_SECTION("stopped in stage 4 after " << after << " results") {
      const auto path = scratch_path("skip-stopped.h5");
      auto stopped = skipping;
      stopped.chain.signal = SIGTERM;
      stopped.chain.signal_stage = 4;
      stopped.chain.signal_after = after;
      REQUIRE(run_chain(stopped, path) == exit_interrupted);
      auto resumed = skipping;
      resumed.resume = true;
      REQUIRE(run_chain(resumed, path) == exit_success);
      CHECK(same_numbers(table(path, "chain/value"), table(reference, "chain/value")));
    }
  }
}

TEST_CASE("the checkpoint keeps only results that later stages still read") {
  const auto path = scratch_path("state.h5");
  ChainRun run = uneven(2);
  run.chain.stages = 6;
  run.chain.result_bytes = 4096;
  run.chain.signal = SIGTERM;
  run.chain.signal_stage = 4;
  REQUIRE(run_chain(run, path) == exit_interrupted);
  const auto saved = store::read_checkpoint(store::checkpoint_path_for(path)).state;
  CHECK(saved.stage == 4);
  CHECK(saved.done.empty());
  REQUIRE(saved.retained.size() == 12);
  for (const auto& [id, result] : saved.retained) CHECK(id.stage == 3);
  // Stages 0-3 left blocks in the journal, but their state is gone: the checkpoint holds one stage's.
  CHECK(std::filesystem::file_size(store::checkpoint_path_for(path)) < 12 * 4096 + 4096);
}

TEST_CASE("a failing item fails the job, naming it, and leaves a checkpoint") {
  const auto path = scratch_path("failing.h5");
  ChainRun run = uneven(2);
  run.chain.fail_stage = 1;
  run.chain.fail_item = 7;
  REQUIRE(run_chain(run, path) == exit_run_failure);
  CHECK(store::read_result_summary(path).state == store::RunStatus::failed);
  CHECK(std::filesystem::exists(store::checkpoint_path_for(path)));
}
