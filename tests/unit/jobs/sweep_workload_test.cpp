// The sweep workload as the runtime sees it: stages and items from the schedule, warm starts passed as
// item inputs from kept results, results placed at their cell in a group per model and level.
#include <catch2/catch_test_macros.hpp>
#include <cstdio>
#include <algorithm>

#include <cmath>

#include "pbrfit/jobs/job_kinds.hpp"
#include "pbrfit/jobs/sweep/cell_result.hpp"
#include "pbrfit/jobs/sweep/sweep_kind.hpp"
#include "pbrfit/jobs/sweep/sweep_workload.hpp"

using namespace pbrfit;
using namespace pbrfit::jobs::sweep;

namespace {

const char* job_text = R"(name: t
kind: sweep
sweep:
  problem: ltc_ggx
  axes: [{name: sqrt_one_minus_cos, count: 3}, {name: roughness, count: 5}]
  levels: 2
  march: {axis: sqrt_one_minus_cos}
  fit: {global_search: never}
  objective: {samples: 128, judge_samples: 128}
)";

SweepWorkload workload() {
  const auto job = spec::parse_job_text(job_text, "t.yaml", jobs::kind_catalogue());
  return SweepWorkload(sweep_settings(job.kind_section));
}

Bytes run(const SweepWorkload& w, WorkItemId id, const ItemResults& kept) {
  const Bytes context, input = w.item_input(id.stage, id.item, kept);
  return w.compute(runtime::ItemTask{id, context, input, 7});
}

// Runs every stage in order, keeping what kept_through() says is still needed.
ItemResults run_all(const SweepWorkload& w) {
  ItemResults kept, all;
  for (std::uint32_t s = 0; s < w.stage_count(); ++s) {
    for (std::uint64_t i = 0; i < w.item_count(s); ++i) all[{s, i}] = kept[{s, i}] = run(w, {s, i}, kept);
    std::erase_if(kept, [&](const auto& entry) { return w.kept_through(entry.first) <= s; });
  }
  return all;
}

}  // namespace

TEST_CASE("a sweep's layout has a group per model and level over that level's axes") {
  const auto w = workload();
  const auto layout = w.layout();
  REQUIRE(layout.groups.size() == 2);
  CHECK(layout.groups[0].name == "ltc/level0");
  CHECK(layout.groups[1].name == "ltc/level1");
  CHECK(layout.groups[0].axis("roughness").values.size() == 3);
  CHECK(layout.groups[1].axis("roughness").values.size() == 5);
  CHECK(layout.groups[1].axis("ltc_1_component").values.size() == 4);
  CHECK(w.stage_count() == 2 + 3);  // level 0: 2 marching steps; level 1: 3
}

TEST_CASE("a cell's input holds the fits of its sources, and only kept results are read") {
  const auto w = workload();
  CHECK_THROWS_AS(w.item_input(2, 0, {}), std::logic_error);  // level 1 needs its parent
  const auto all = run_all(w);  // throws if a source was dropped too early
  CHECK(all.size() == 6 + 15);
}

TEST_CASE("a sweep's results are a pure function of the job, its item and its input") {
  const auto a = run_all(workload());
  const auto b = run_all(workload());
  CHECK(a == b);
  const auto w = workload();
  const auto blocks = w.blocks({4, 1}, a.at({4, 1}));
  bool found_error = false;
  for (const auto& block : blocks) {
    CHECK((block.group == "ltc/level1"));
    if (block.table == "error") {
      found_error = true;
      CHECK(block.offset == std::vector<std::uint64_t>{2, 1});  // last marching step, second roughness
      CHECK(std::isfinite(block.values[0].real()));
    }
    if (block.table == "ltc_1") CHECK(block.count == std::vector<std::uint64_t>{1, 1, 4});
  }
  CHECK(found_error);
  CHECK_THROWS_AS(w.blocks({4, 1}, Bytes(3)), RunError);
  CHECK(w.headline({}) == "no cells fitted yet");
}

// The headline gives the error as bounds that half and 95 % of the cells do not exceed (percentiles by
// 1/8-decade bins: true bounds, at most 1/8 decade above the exact percentiles), not a min..max range.
TEST_CASE("a sweep's headline bounds the errors of half and 95 % of the cells") {
  const auto w = workload();
  const auto all = run_all(w);
  Bytes summary;
  std::vector<double> errors;
  for (const auto& [id, result] : all) {
    w.fold_summary(summary, id, result);
    for (const auto& block : w.blocks(id, result))
      if (block.table == "error") errors.push_back(block.values[0].real());
  }
  std::sort(errors.begin(), errors.end());
  const std::string headline = w.headline(summary);
  INFO(headline);
  const auto at = headline.find("error: half the cells <= ");
  REQUIRE(at != std::string::npos);
  double half = 0.0, most = 0.0;
  REQUIRE(std::sscanf(headline.c_str() + at, "error: half the cells <= %lf, 95%% <= %lf", &half, &most) == 2);
  const double exact_half = errors[std::size_t(std::ceil(0.5 * double(errors.size()))) - 1];
  const double exact_most = errors[std::size_t(std::ceil(0.95 * double(errors.size()))) - 1];
  const double bin = std::pow(10.0, 1.0 / 8.0) * 1.005;  // a bin, and the headline's 3 digits
  CHECK(half >= exact_half / 1.005);  // printed to 3 digits
  CHECK(half <= exact_half * bin);
  CHECK(most >= exact_most / 1.005);
  CHECK(most <= exact_most * bin);
  CHECK(headline.find("..") == std::string::npos);
}
