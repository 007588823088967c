// The sweep workload as the runtime sees it: stages and items from the schedule, warm starts passed as
// item inputs from kept results, results placed at their cell in a group per model and level.
#include <catch2/catch_test_macros.hpp>
#include <cstdio>
#include <algorithm>

#include <cmath>
#include <map>
#include <string>

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
  objective: {samples: 128, judge_samples: 128, render_size: 0}
)";

SweepWorkload workload(const std::string& text = job_text) {
  const auto job = spec::parse_job_text(text, "t.yaml", jobs::kind_catalogue());
  return SweepWorkload(sweep_settings(job.kind_section));
}

// A one-level table on the published table's grid (every third texel of 64) with a check render of 16 x 16.
const char* rendering_job = R"(name: t
kind: sweep
sweep:
  problem: ltc_ggx
  axes: [{name: sqrt_one_minus_cos, count: 4}, {name: roughness, count: 4}]
  march: {axis: sqrt_one_minus_cos}
  fit: {global_search: never}
  objective: {samples: 128, judge_samples: 128, polygon_quads: 0, render_size: 16}
)";

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

// The headline gives an LTC table's relative L2 error (error_l2 over the target's own L2 norm) in per cent,
// as bounds that half and 95 % of the cells do not exceed (percentiles by 1/8-decade bins: true bounds, at
// most 1/8 decade above the exact percentiles), not a min..max range of the absolute fitting objective.
TEST_CASE("a sweep's headline bounds the relative errors of half and 95 % of the cells") {
  const auto w = workload();
  const auto all = run_all(w);
  Bytes summary;
  std::vector<double> errors;
  for (const auto& [id, result] : all) {
    w.fold_summary(summary, id, result);
    for (const auto& block : w.blocks(id, result))
      if (block.table == "error_l2_relative") errors.push_back(100.0 * block.values[0].real());
  }
  REQUIRE(errors.size() >= 15);  // every cell of both levels
  std::sort(errors.begin(), errors.end());
  CHECK(errors.front() > 0.0);
  CHECK(std::isfinite(errors.back()));
  const std::string headline = w.headline(summary);
  INFO(headline);
  const auto at = headline.find("ltc relative L2 error: half the cells <= ");
  REQUIRE(at != std::string::npos);
  double half = 0.0, most = 0.0;
  REQUIRE(std::sscanf(headline.c_str() + at, "ltc relative L2 error: half the cells <= %lf%%, 95%% <= %lf%%", &half,
                      &most) == 2);
  const double exact_half = errors[std::size_t(std::ceil(0.5 * double(errors.size()))) - 1];
  const double exact_most = errors[std::size_t(std::ceil(0.95 * double(errors.size()))) - 1];
  const double bin = std::pow(10.0, 1.0 / 8.0) * 1.005;  // a bin, and the headline's 3 digits
  CHECK(half >= exact_half / 1.005);  // printed to 3 digits
  CHECK(half <= exact_half * bin);
  CHECK(most >= exact_most / 1.005);
  CHECK(most <= exact_most * bin);
  CHECK(headline.find("..") == std::string::npos);
}

// The check render: a last stage of bands of rows per image, at the roughness grid values nearest 0.25, 0.5
// and 0.75 (here 1/3 twice, and 2/3), whose pixels are the finished table as a shader reads it beside the
// lobe's own integral and the published table read the same way.
TEST_CASE("an LTC sweep renders its finished table beside ground truth and the published table") {
  const auto w = workload(rendering_job);
  const auto layout = w.layout();
  REQUIRE(layout.groups.size() == 3);
  const auto& group = layout.groups[1];
  CHECK(group.name == "ltc/render");
  CHECK(group.axis("roughness").values == std::vector<double>{1.0 / 3.0, 2.0 / 3.0});
  CHECK(group.axis("row").values.size() == 16);
  REQUIRE(group.tables.size() == 3);
  CHECK(group.tables[0].name == "ltc");
  CHECK(group.tables[1].name == "reference");
  CHECK(group.tables[2].name == "published");
  const std::uint32_t render = w.stage_count() - 1;
  CHECK(render == 4);  // after the 4 marching steps
  REQUIRE(w.item_count(render) == 2 * 2);  // 2 images of 2 bands of 8 rows

  const auto all = run_all(w);  // the last level is kept until the render has read it
  const auto again = run_all(workload(rendering_job));
  CHECK(all == again);
  const auto& lobes = layout.groups[2];
  CHECK(lobes.name == "ltc/lobes");
  CHECK(lobes.axis("view_degrees").values.size() == 2);  // the grid's views nearest 30 and 70 degrees
  CHECK(lobes.axis("light_degrees").values.size() == 181);
  std::map<std::string, std::vector<double>> image, lobe;  // the first image, 1/3, row-major
  for (std::uint64_t item = 0; item < 2; ++item) {
    for (const auto& block : w.blocks({render, item}, all.at({render, item}))) {
      if (block.group == "ltc/lobes") {
        CHECK(item == 0);  // written with the first band
        CHECK(block.offset == std::vector<std::uint64_t>{0, 0, 0});
        CHECK(block.count == std::vector<std::uint64_t>{1, 2, 181});
        for (const auto& v : block.values) lobe[block.table].push_back(v.real());
        continue;
      }
      CHECK(block.group == "ltc/render");
      CHECK(block.offset == std::vector<std::uint64_t>{0, 8 * item, 0});
      CHECK(block.count == std::vector<std::uint64_t>{1, 8, 16});
      for (const auto& v : block.values) image[block.table].push_back(v.real());
    }
  }
  REQUIRE(image["reference"].size() == 256);
  double lit = 0.0, ours = 0.0, difference = 0.0, published = 0.0;
  for (std::size_t i = 0; i < 256; ++i) {
    REQUIRE(std::isfinite(image["reference"][i]));  // every pixel of this scene sees the plane
    lit += image["reference"][i];
    ours += image["ltc"][i];
    difference += std::abs(image["ltc"][i] - image["reference"][i]);
    published += std::abs(image["published"][i] - image["reference"][i]);
  }
  CHECK(lit > 0.0);
  // The 4 x 4 table of coarse fits lights the plane as a whole within 4 % of the truth (2.9 % today), pixel by
  // pixel within 15 % (10.7 %); the published table, read at the same 4 texels per view, is an independent
  // check of both (9.1 %).
  CHECK(std::abs(ours - lit) < 0.04 * lit);
  CHECK(difference < 0.15 * lit);
  CHECK(published < 0.15 * lit);

  // The lobes: the fitted LTC close to its GGX target in the plane of incidence, as the published texel is.
  REQUIRE(lobe["target"].size() == 2 * 181);
  for (std::size_t view = 0; view < 2; ++view) {
    double target = 0.0, ltc_off = 0.0, published_off = 0.0;
    for (std::size_t i = view * 181; i < (view + 1) * 181; ++i) {
      target += lobe["target"][i];
      ltc_off += std::abs(lobe["ltc"][i] - lobe["target"][i]);
      published_off += std::abs(lobe["published"][i] - lobe["target"][i]);
    }
    INFO("view " << view << ": target " << target << ", ltc off " << ltc_off << ", published off " << published_off);
    CHECK(target > 0.0);
    CHECK(ltc_off < 0.08 * target);  // 0.5 % and 3.3 % today
    CHECK(published_off < 0.08 * target);
  }
}

TEST_CASE("render_size 0 leaves the render out") {
  const auto w = workload();
  for (const auto& g : w.layout().groups) CHECK(g.name.find("render") == std::string::npos);
  CHECK(w.item_count(w.stage_count() - 1) > 0);  // the last stage is a level, not an empty render
}
