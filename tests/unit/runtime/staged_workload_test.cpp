// runtime/staged_workload.hpp: a plan of typed entries is seen by the runtime as the stages, items,
// contexts, inputs and results it describes; step numbers are relative to their entry; a result that fails
// its stage's check, a truncated result and a stage past the plan are errors.
#include <catch2/catch_test_macros.hpp>

#include "pbrfit/runtime/staged_workload.hpp"

using namespace pbrfit;

namespace {

struct CountSummary {
  std::uint64_t results = 0, sum = 0;
};

struct Grown {
  std::uint64_t value = 0;
  std::vector<std::uint64_t> history;
  template <class Archive>
  void serialize(Archive& archive) {
    archive(value, history);
  }
};

struct Totals {
  std::vector<std::uint64_t> values;
  template <class Archive>
  void serialize(Archive& archive) {
    archive(values);
  }
};

// What the coordinator does, stage by stage, in one process: the blocks written, the summary and what is
// still kept at the end.
struct PlanRun {
  std::vector<store::Block> written;
  Bytes summary;
  ItemResults kept;
};
PlanRun run_plan(const runtime::Workload& workload) {
  PlanRun run;
  const std::atomic<bool> cancelled{false};
  for (std::uint32_t stage = 0; stage < workload.stage_count(); ++stage) {
    const Bytes context = workload.stage_context(stage, run.kept);
    for (std::uint64_t item = 0; item < workload.item_count(stage); ++item) {
      const Bytes input = workload.item_input(stage, item, run.kept);
      const WorkItemId id{stage, item};
      const Bytes result = workload.compute({id, context, input, 7, &cancelled});
      for (auto& block : workload.blocks(id, result)) run.written.push_back(std::move(block));
      workload.fold_summary(run.summary, id, result);
      run.kept[id] = result;
    }
    std::erase_if(run.kept, [&](const auto& entry) { return workload.kept_through(entry.first) <= stage; });
  }
  return run;
}

// Two "grow" stages (step s has s + 2 items; item i of step 1 starts from item i % 2 of step 0), then one
// "total" stage whose context is every result of the last grow stage.
class Toy final : public runtime::StagedWorkload<CountSummary> {
 public:
  Toy() {
    add_stage(runtime::stage<Nothing, Grown, Grown>("grow", 2, this)
                  .items(&Toy::grow_items)
                  .input(&Toy::grow_input)
                  .compute(&Toy::grow)
                  .blocks(&Toy::grow_blocks)
                  .kept_through(&Toy::grow_kept)
                  .fold(&Toy::fold_grown));
    add_stage(runtime::stage<Totals, Nothing, std::uint64_t>("total", 1, this)
                  .items(&Toy::one)
                  .context(&Toy::total_context)
                  .compute(&Toy::total)
                  .check(&Toy::check_total)
                  .blocks(&Toy::total_blocks));
  }
  store::ResultLayout layout() const override { return {}; }
  std::uint32_t total_stage() const { return first_stage("total"); }

 private:
  std::uint64_t grow_items(std::uint32_t step) const { return step + 2; }
  std::uint64_t one(std::uint32_t) const { return 1; }
  Grown grow_input(std::uint32_t step, std::uint64_t item, const runtime::KeptResults& kept) const {
    if (step == 0) return {};
    return kept.at<Grown>({0, item % 2});
  }
  Grown grow(const runtime::StageTask<Nothing, Grown>& task) const {
    Grown out = task.input;
    out.value = out.value * 10 + task.item() + 1;
    out.history.push_back(task.step());
    return out;
  }
  std::vector<store::Block> grow_blocks(const runtime::StageItem& at, const Grown& g) const {
    return {{"grow", "value", {at.step, at.item()}, {1, 1}, {double(g.value)}}};
  }
  std::uint32_t grow_kept(const runtime::StageItem& at) const { return at.step == 0 ? 1 : 2; }
  void fold_grown(Summary& s, const runtime::StageItem&, const Grown& g) const {
    ++s.results;
    s.sum += g.value;
  }
  Totals total_context(std::uint32_t, const runtime::KeptResults& kept) const {
    Totals t;
    for (std::uint64_t item = 0; item < 3; ++item) t.values.push_back(kept.at<Grown>("grow", 1, item).value);
    return t;
  }
  std::uint64_t total(const runtime::StageTask<Totals, Nothing>& task) const {
    std::uint64_t sum = 0;
    for (auto v : task.context.values) sum += v;
    return sum;
  }
  void check_total(const runtime::StageItem&, const std::uint64_t& value) const {
    if (value == 0) throw RunError("an empty total");
  }
  std::vector<store::Block> total_blocks(const runtime::StageItem&, const std::uint64_t& value) const {
    return {{"total", "sum", {0}, {1}, {double(value)}}};
  }
  std::string headline_of(const Summary& s) const override {
    return std::to_string(s.results) + " results, sum " + std::to_string(s.sum);
  }
};

}  // namespace

TEST_CASE("a staged workload runs its plan through the runtime's interface") {
  const Toy toy;
  REQUIRE(toy.stage_count() == 3);
  CHECK(toy.item_count(0) == 2);
  CHECK(toy.item_count(1) == 3);
  CHECK(toy.item_count(2) == 1);
  CHECK(toy.total_items() == 6);
  CHECK(toy.total_stage() == 2);

  const auto [written, summary, kept] = run_plan(toy);
  // Stage 0: 1, 2. Stage 1 (from items 0, 1, 0 of stage 0): 11, 22, 13. Total: 46.
  REQUIRE(written.size() == 6);
  CHECK(written[2].values == store::reals(std::vector<double>{11}));
  CHECK(written[3].values == store::reals(std::vector<double>{22}));
  CHECK(written[4].values == store::reals(std::vector<double>{13}));
  CHECK(written[4].offset == std::vector<std::uint64_t>{1, 2});  // the step, not the stage number
  CHECK(written[5].values == store::reals(std::vector<double>{46}));
  CHECK(toy.headline(summary) == "5 results, sum 49");
  CHECK(toy.headline({}) == "0 results, sum 0");
  CHECK(kept.empty());
}

TEST_CASE("a staged workload refuses results it cannot read and stages past its plan") {
  const Toy toy;
  const Bytes zero = to_bytes(std::uint64_t{0});
  CHECK_THROWS_AS(toy.blocks({2, 0}, zero), RunError);  // fails the stage's check
  Bytes truncated = to_bytes(Grown{5, {1, 2}});
  truncated.pop_back();
  CHECK_THROWS_AS(toy.blocks({0, 0}, truncated), RunError);
  CHECK_THROWS_AS(toy.item_count(3), RunError);
  const ItemResults nothing;
  const runtime::KeptResults none{nothing};
  CHECK_THROWS_AS(none.at<Grown>({0, 0}), std::logic_error);  // a result the plan did not keep
}

namespace {

// A cycle of 3 steps, each two stages: "seed" (2 items) with "sum" (1 item) beside it, then "scale"
// (1 item) whose context is the step's seeds; then "last" (1 item) reading the last step's scale.
// seed i at step s is 10 s + i; sum at step s adds the seeds of step s - 1 and the scale of step s - 1;
// scale at step s is 2 x the sum of the step's seeds.
class Cycled final : public runtime::StagedWorkload<CountSummary> {
 public:
  Cycled() {
    const auto seed = runtime::stage<Nothing, Nothing, std::uint64_t>("seed", 1, this)
                          .items(&Cycled::two)
                          .compute(&Cycled::seed)
                          .blocks(&Cycled::place_of)
                          .kept_through(&Cycled::next_step)
                          .fold(&Cycled::count);
    const auto sum = runtime::stage<Nothing, Totals, std::uint64_t>("sum", 1, this)
                         .items(&Cycled::one)
                         .input(&Cycled::sum_input)
                         .compute(&Cycled::add)
                         .blocks(&Cycled::place_of);
    const auto scale = runtime::stage<Totals, Nothing, std::uint64_t>("scale", 1, this)
                           .items(&Cycled::one)
                           .context(&Cycled::seeds_of_step)
                           .compute(&Cycled::scale)
                           .blocks(&Cycled::place_of)
                           .kept_through(&Cycled::next_step);
    add_cycle(3, {runtime::parts(seed, sum), runtime::parts(scale)});
    add_stage(runtime::stage<Nothing, std::uint64_t, std::uint64_t>("last", 1, this)
                  .items(&Cycled::one)
                  .input(&Cycled::last_input)
                  .compute(&Cycled::echo)
                  .blocks(&Cycled::place_of));
  }
  store::ResultLayout layout() const override { return {}; }
  std::uint32_t number(std::string_view part, std::uint32_t step) const { return stage_number(part, step); }

 private:
  std::uint64_t one(std::uint32_t) const { return 1; }
  std::uint64_t two(std::uint32_t) const { return 2; }
  std::uint64_t seed(const runtime::StageTask<Nothing, Nothing>& task) const { return 10 * task.step() + task.item(); }
  Totals sum_input(std::uint32_t step, std::uint64_t, const runtime::KeptResults& kept) const {
    if (step == 0) return {};
    return {{kept.at<std::uint64_t>("seed", step - 1, 0), kept.at<std::uint64_t>("seed", step - 1, 1),
             kept.at<std::uint64_t>("scale", step - 1, 0)}};
  }
  std::uint64_t add(const runtime::StageTask<Nothing, Totals>& task) const {
    std::uint64_t total = 0;
    for (auto v : task.input.values) total += v;
    return total;
  }
  Totals seeds_of_step(std::uint32_t step, const runtime::KeptResults& kept) const {
    return {{kept.at<std::uint64_t>("seed", step, 0), kept.at<std::uint64_t>("seed", step, 1)}};
  }
  std::uint64_t scale(const runtime::StageTask<Totals, Nothing>& task) const {
    return 2 * (task.context.values.at(0) + task.context.values.at(1));
  }
  std::uint64_t last_input(std::uint32_t, std::uint64_t, const runtime::KeptResults& kept) const {
    return kept.at<std::uint64_t>("scale", 2, 0);
  }
  std::uint64_t echo(const runtime::StageTask<Nothing, std::uint64_t>& task) const { return task.input; }
  // Kept until the next step's first stage (or "last") is done.
  std::uint32_t next_step(const runtime::StageItem& at) const { return number("scale", at.step) + 1; }
  // Value, stage, step and index within the part.
  std::vector<store::Block> place_of(const runtime::StageItem& at, const std::uint64_t& value) const {
    return {{"cycle", "values", {0}, {1}, {double(value), double(at.id.stage), double(at.step), double(at.index)}}};
  }
  void count(Summary& s, const runtime::StageItem&, const std::uint64_t& v) const {
    ++s.results;
    s.sum += v;
  }
  std::string headline_of(const Summary& s) const override { return std::to_string(s.results) + " seeds"; }
};

}  // namespace

TEST_CASE("a cycle repeats its stages, and parts of a stage split its items") {
  const Cycled plan;
  REQUIRE(plan.stage_count() == 7);
  for (std::uint32_t s = 0; s < 6; s += 2) {
    CHECK(plan.item_count(s) == 3);  // two seeds and the sum
    CHECK(plan.item_count(s + 1) == 1);
  }
  CHECK(plan.item_count(6) == 1);
  CHECK(plan.number("seed", 2) == 4);
  CHECK(plan.number("sum", 1) == 2);
  CHECK(plan.number("scale", 1) == 3);
  CHECK(plan.number("last", 0) == 6);
  CHECK_THROWS_AS(plan.number("scale", 3), std::logic_error);  // past the cycle
  CHECK_THROWS_AS(plan.number("nothing", 0), std::logic_error);
  CHECK_THROWS_AS(plan.item_count(7), RunError);
  CHECK_THROWS_AS(plan.blocks({0, 3}, to_bytes(std::uint64_t{1})), RunError);  // past the stage's parts

  const auto [blocks, summary, kept] = run_plan(plan);
  std::vector<std::vector<double>> written;
  for (const auto& block : blocks) {
    written.emplace_back();
    for (const auto& v : block.values) written.back().push_back(v.real());
  }
  // Step 0: seeds 0, 1, sum 0, scale 2. Step 1: seeds 10, 11, sum 0 + 1 + 2 = 3, scale 42.
  // Step 2: seeds 20, 21, sum 10 + 11 + 42 = 63, scale 82. Last: 82.
  const std::vector<std::vector<double>> expected = {
      {0, 0, 0, 0},  {1, 0, 0, 1},  {0, 0, 0, 0},  {2, 1, 0, 0},  {10, 2, 1, 0},  {11, 2, 1, 1}, {3, 2, 1, 0},
      {42, 3, 1, 0}, {20, 4, 2, 0}, {21, 4, 2, 1}, {63, 4, 2, 0}, {82, 5, 2, 0}, {82, 6, 0, 0}};
  CHECK(written == expected);
  CHECK(plan.headline(summary) == "6 seeds");
  CHECK(kept.empty());
}

namespace {

// Plans that cannot be: two parts of one name, a cycle's part repeating on its own, two contexts in a stage.
class BadPlan final : public runtime::StagedWorkload<CountSummary> {
 public:
  explicit BadPlan(int mistake) {
    const auto a = runtime::stage<Nothing, Nothing, std::uint64_t>("a", mistake == 1 ? 2 : 1, this)
                       .items(&BadPlan::one)
                       .compute(&BadPlan::zero)
                       .blocks(&BadPlan::none);
    const auto b = runtime::stage<std::uint64_t, Nothing, std::uint64_t>(mistake == 0 ? "a" : "b", 1, this)
                       .items(&BadPlan::one)
                       .context(&BadPlan::context)
                       .compute(&BadPlan::zero_from)
                       .blocks(&BadPlan::none);
    const auto c = runtime::stage<std::uint64_t, Nothing, std::uint64_t>("c", 1, this)
                       .items(&BadPlan::one)
                       .context(&BadPlan::context)
                       .compute(&BadPlan::zero_from)
                       .blocks(&BadPlan::none);
    if (mistake == 2) add_stage(b, c);
    else add_cycle(2, {runtime::parts(a), runtime::parts(b)});
  }
  store::ResultLayout layout() const override { return {}; }

 private:
  std::uint64_t one(std::uint32_t) const { return 1; }
  std::uint64_t zero(const runtime::StageTask<Nothing, Nothing>&) const { return 0; }
  std::uint64_t zero_from(const runtime::StageTask<std::uint64_t, Nothing>&) const { return 0; }
  std::uint64_t context(std::uint32_t, const runtime::KeptResults&) const { return 0; }
  std::vector<store::Block> none(const runtime::StageItem&, const std::uint64_t&) const { return {}; }
  std::string headline_of(const Summary&) const override { return {}; }
};

}  // namespace

TEST_CASE("a plan that cannot be is refused when it is made") {
  CHECK_THROWS_AS(BadPlan(0), std::logic_error);
  CHECK_THROWS_AS(BadPlan(1), std::logic_error);
  CHECK_THROWS_AS(BadPlan(2), std::logic_error);
  CHECK_NOTHROW(BadPlan(3));
}
