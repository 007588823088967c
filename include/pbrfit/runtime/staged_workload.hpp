#pragma once
// Typed stages over the runtime's contract (runtime/workload.hpp). A kind derives from
// StagedWorkload<Summary> and lists its stages once, in order, in its constructor; that list is the kind's
// stage plan. Each stage is made of one or more named parts, each part a run of items with its own types
// and the kind's member functions that serve it:
//
//     add_stage(runtime::stage<Nothing, Nothing, Row>("rows", 1, this)
//                   .items(&DfgTable::row_count)       // std::uint64_t (std::uint32_t step) const
//                   .compute(&DfgTable::compute_row)   // Row (const runtime::StageTask<Nothing, Nothing>&) const
//                   .blocks(&DfgTable::row_blocks)     // std::vector<store::Block> (const StageItem&, const Row&) const
//                   .fold(&DfgTable::fold_row));       // void (Summary&, const StageItem&, const Row&) const
//
// The count after the name repeats the stage (one per sweep level, per migration epoch): the repetitions
// are its steps. A stage of several parts splits its items among them in order (`add_stage(a, b)`: a's
// items first), and a cycle repeats a sequence of stages (`add_cycle(generations, {parts(breed, front),
// parts(evaluate)})`: breed and front, then evaluate, once per generation, the generation being the step).
//
// Optional: .context(step, kept) -> Context, sent once to every rank (at most one part of a stage has
// one; the others read Nothing); .input(step, index, kept) -> Input, sent with the item; .check(item,
// result) throws RunError on a result that cannot be the part's (it runs before blocks and fold; bytes
// that do not decode are a RunError too); .kept_through(item) -> the last stage that reads the result
// (default: its own; stage_number() names a stage of the plan).
// The types say what crosses ranks and checkpoints; core/serial.hpp encodes them, so a kind never handles
// bytes, and a hook receives its place in the plan (the step, and the item's index within its part)
// instead of computing what a stage or item number means; KeptResults finds earlier results by part, step
// and index. The contract of workload.hpp holds unchanged: compute is pure, context and input read only
// kept results, fold is order-independent.
#include <algorithm>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "pbrfit/core/error.hpp"
#include "pbrfit/core/serial.hpp"
#include "pbrfit/runtime/workload.hpp"

namespace pbrfit::runtime {

// One item as the hooks of a part see it: its id, its step (the repetition of its stage) and its index
// among the part's items (the id's item less the items of the parts before it in the stage).
struct StageItem {
  WorkItemId id;
  std::uint32_t step = 0;
  std::uint64_t index = 0;
  std::uint64_t item() const { return index; }
};

// What compute() receives: the decoded context and input with the item's id, step and random streams.
template <class Context, class Input>
struct StageTask {
  StageItem at;
  const Context& context;
  const Input& input;
  const ItemTask& task;

  std::uint64_t item() const { return at.index; }
  std::uint32_t step() const { return at.step; }
  RandomStream random(std::uint64_t substream = 0) const { return task.random(substream); }
  bool stop_requested() const { return task.stop_requested(); }
  std::uint64_t seed() const { return task.seed; }
};

// Where a named part of the plan puts its results: part `part`'s item `index` at step `step`.
class StageLocator {
 public:
  virtual WorkItemId locate(std::string_view part, std::uint32_t step, std::uint64_t index) const = 0;

 protected:
  ~StageLocator() = default;
};

// The results earlier stages kept (workload.hpp, kept_through), read as their types: by the part of the
// plan that produced them, or by item id.
class KeptResults {
 public:
  explicit KeptResults(const ItemResults& kept, const StageLocator* plan = nullptr) : kept_(kept), plan_(plan) {}
  // It refers to the results it is given: a temporary would be gone before the first read (ASan found a
  // test doing that, staged_workload_test.cpp), so one does not compile.
  explicit KeptResults(ItemResults&&, const StageLocator* = nullptr) = delete;

  template <class Result>
  Result at(WorkItemId id) const {
    const auto found = kept_.find(id);
    if (found == kept_.end())  // the plan's kept_through() let it go: a bug in the kind
      throw std::logic_error("result of stage " + std::to_string(id.stage) + " item " + std::to_string(id.item) +
                     " is not kept");
    return from_bytes<Result>(found->second);
  }
  // Item `index` of part `part` at step `step`.
  template <class Result>
  Result at(std::string_view part, std::uint32_t step, std::uint64_t index) const {
    if (!plan_) throw std::logic_error("kept results read by part without a plan");
    return at<Result>(plan_->locate(part, step, index));
  }
  const ItemResults& bytes() const { return kept_; }

 private:
  const ItemResults& kept_;
  const StageLocator* plan_;
};

// A part of the plan with its types erased to the runtime's bytes.
template <class Summary>
struct PlannedStage {
  std::string name;
  std::uint32_t stages = 1;  // repetitions of its stage
  bool has_context = false;
  std::function<std::uint64_t(std::uint32_t step)> items;
  std::function<Bytes(std::uint32_t step, const KeptResults&)> context;
  std::function<Bytes(std::uint32_t step, std::uint64_t item, const KeptResults&)> input;
  std::function<Bytes(const StageItem&, const ItemTask&)> compute;
  std::function<std::vector<store::Block>(const StageItem&, const Bytes&)> blocks;
  std::function<std::uint32_t(const StageItem&)> kept_through;
  std::function<void(Summary&, const StageItem&, const Bytes&)> fold;
};

// Binds a kind's member functions to a plan entry of types Context, Input and Result.
template <class Kind, class Context, class Input, class Result>
class StageBuilder {
 public:
  using Summary = typename Kind::Summary;
  using Task = StageTask<Context, Input>;

  StageBuilder(std::string name, std::uint32_t stages, const Kind* kind) : kind_(kind) {
    planned_.name = std::move(name);
    planned_.stages = stages;
    planned_.context = [](std::uint32_t, const KeptResults&) { return to_bytes(Context{}); };
    planned_.input = [](std::uint32_t, std::uint64_t, const KeptResults&) { return to_bytes(Input{}); };
    planned_.kept_through = [](const StageItem& at) { return at.id.stage; };
    planned_.fold = [](Summary&, const StageItem&, const Bytes&) {};
  }

  template <class F>
  StageBuilder& items(F f) {
    planned_.items = [k = kind_, f](std::uint32_t step) { return std::uint64_t(std::invoke(f, k, step)); };
    return *this;
  }
  template <class F>
  StageBuilder& context(F f) {
    planned_.context = [k = kind_, f](std::uint32_t step, const KeptResults& kept) {
      return to_bytes<Context>(std::invoke(f, k, step, kept));
    };
    planned_.has_context = true;
    return *this;
  }
  template <class F>
  StageBuilder& input(F f) {
    planned_.input = [k = kind_, f](std::uint32_t step, std::uint64_t item, const KeptResults& kept) {
      return to_bytes<Input>(std::invoke(f, k, step, item, kept));
    };
    return *this;
  }
  template <class F>
  StageBuilder& compute(F f) {
    planned_.compute = [k = kind_, f](const StageItem& at, const ItemTask& task) {
      // A part without a context of its own shares its stage with one that has: it reads Nothing.
      Context context{};
      if constexpr (!std::is_same_v<Context, Nothing>) context = from_bytes<Context>(task.context);
      const auto input = from_bytes<Input>(task.input);
      return to_bytes<Result>(std::invoke(f, k, Task{at, context, input, task}));
    };
    return *this;
  }
  template <class F>
  StageBuilder& check(F f) {
    check_ = [k = kind_, f](const StageItem& at, const Result& result) { std::invoke(f, k, at, result); };
    return *this;
  }
  template <class F>
  StageBuilder& blocks(F f) {
    blocks_ = [k = kind_, f](const StageItem& at, const Result& result) { return std::invoke(f, k, at, result); };
    return *this;
  }
  template <class F>
  StageBuilder& kept_through(F f) {
    planned_.kept_through = [k = kind_, f](const StageItem& at) { return std::uint32_t(std::invoke(f, k, at)); };
    return *this;
  }
  template <class F>
  StageBuilder& fold(F f) {
    fold_ = [k = kind_, f](Summary& summary, const StageItem& at, const Result& result) {
      std::invoke(f, k, summary, at, result);
    };
    return *this;
  }

  // The entry with its types erased; a missing items, compute or blocks is a programming error.
  PlannedStage<Summary> planned() const {
    if (!planned_.items || !planned_.compute || !blocks_)
      throw std::logic_error("stage '" + planned_.name + "' needs items, compute and blocks");
    PlannedStage<Summary> out = planned_;
    auto decode = [check = check_, name = planned_.name](const StageItem& at, const Bytes& bytes) {
      Result result;
      try {
        result = from_bytes<Result>(bytes);
      } catch (const ByteFormatError& e) {
        throw RunError("a result of stage '" + name + "' is damaged: " + e.what() + " at byte " +
                       std::to_string(e.offset()));
      }
      if (check) check(at, result);
      return result;
    };
    out.blocks = [decode, blocks = blocks_](const StageItem& at, const Bytes& bytes) {
      return blocks(at, decode(at, bytes));
    };
    if (fold_)
      out.fold = [decode, fold = fold_](Summary& summary, const StageItem& at, const Bytes& bytes) {
        fold(summary, at, decode(at, bytes));
      };
    return out;
  }

 private:
  const Kind* kind_;
  PlannedStage<Summary> planned_;
  std::function<void(const StageItem&, const Result&)> check_;
  std::function<std::vector<store::Block>(const StageItem&, const Result&)> blocks_;
  std::function<void(Summary&, const StageItem&, const Result&)> fold_;
};

// A part named `name` of a stage repeated `stages` times, served by members of *kind.
template <class Context, class Input, class Result, class Kind>
StageBuilder<Kind, Context, Input, Result> stage(std::string name, std::uint32_t stages, const Kind* kind) {
  return {std::move(name), stages, kind};
}

// The erased parts of builders, in order: one stage's parts, for add_cycle.
template <class... Builders>
auto parts(const Builders&... builders) {
  using Summary = typename std::common_type_t<typename Builders::Summary...>;
  return std::vector<PlannedStage<Summary>>{builders.planned()...};
}

// A workload whose stages are a plan of typed parts and whose running summary is a trivially copyable
// Summary (value-initialized before the first result).
template <class SummaryType>
class StagedWorkload : public Workload, private StageLocator {
 public:
  using Summary = SummaryType;
  using Part = PlannedStage<Summary>;
  static_assert(std::is_trivially_copyable_v<Summary>);

  StagedWorkload() = default;
  StagedWorkload(const StagedWorkload&) = delete;  // the plan holds `this`
  StagedWorkload& operator=(const StagedWorkload&) = delete;

  std::uint32_t stage_count() const final {
    std::uint32_t total = 0;
    for (const auto& round : plan_) total += round.repeats * std::uint32_t(round.stages.size());
    return total;
  }
  std::uint64_t item_count(std::uint32_t stage) const final {
    const auto [parts, step] = stage_at(stage);
    std::uint64_t total = 0;
    for (const Part& part : parts) total += part.items(step);
    return total;
  }
  Bytes stage_context(std::uint32_t stage, const ItemResults& kept) const final {
    const auto [parts, step] = stage_at(stage);
    for (const Part& part : parts)
      if (part.has_context) return part.context(step, KeptResults(kept, this));
    return {};
  }
  Bytes item_input(std::uint32_t stage, std::uint64_t item, const ItemResults& kept) const final {
    const auto [part, at] = place({stage, item});
    return part.input(at.step, at.index, KeptResults(kept, this));
  }
  Bytes compute(const ItemTask& task) const final {
    const auto [part, at] = place(task.id);
    return part.compute(at, task);
  }
  std::vector<store::Block> blocks(WorkItemId id, const Bytes& result) const final {
    const auto [part, at] = place(id);
    return part.blocks(at, result);
  }
  std::uint32_t kept_through(WorkItemId id) const final {
    const auto [part, at] = place(id);
    return part.kept_through(at);
  }
  void fold_summary(Bytes& summary, WorkItemId id, const Bytes& result) const final {
    const auto [part, at] = place(id);
    auto value = summary_as<Summary>(summary);
    part.fold(value, at, result);
    store_summary(summary, value);
  }
  std::string headline(const Bytes& summary) const final { return headline_of(summary_as<Summary>(summary)); }
  double work_done(const Bytes& summary) const final { return work_done_in(summary_as<Summary>(summary)); }

 protected:
  // Appends a stage of one or more parts to the plan (in the kind's constructor, in stage order), repeated
  // as often as its parts say (they must agree).
  template <class First, class... Rest>
  void add_stage(const First& first, const Rest&... rest) {
    std::vector<Part> stage{first.planned(), rest.planned()...};
    for (const Part& part : stage)
      if (part.stages != stage.front().stages)
        throw std::logic_error("the parts of stage '" + stage.front().name + "' repeat differently");
    const std::uint32_t repeats = stage.front().stages;
    add_round(repeats, {std::move(stage)});
  }
  // Appends a sequence of stages repeated `repeats` times (each of its parts made with a count of 1).
  void add_cycle(std::uint32_t repeats, std::vector<std::vector<Part>> stages) {
    for (const auto& stage : stages)
      for (const Part& part : stage)
        if (part.stages != 1) throw std::logic_error("part '" + part.name + "' of a cycle repeats on its own");
    add_round(repeats, std::move(stages));
  }
  // The stage number of the part called `name` at `step`.
  std::uint32_t stage_number(std::string_view name, std::uint32_t step = 0) const {
    return find_part(name, step, std::nullopt).stage;
  }
  std::uint32_t first_stage(std::string_view name) const { return stage_number(name, 0); }

  virtual std::string headline_of(const Summary& summary) const = 0;
  virtual double work_done_in(const Summary& /*summary*/) const { return 0.0; }

 private:
  // A sequence of stages repeated `repeats` times; step r of stage s is stage number first + r * size + s.
  struct Round {
    std::uint32_t repeats = 1;
    std::vector<std::vector<Part>> stages;
  };
  struct StageAt {
    const std::vector<Part>& parts;
    std::uint32_t step;
  };
  struct Place {
    const Part& part;
    StageItem at;
  };

  void add_round(std::uint32_t repeats, std::vector<std::vector<Part>> stages) {
    std::vector<std::string> names;
    for (const auto& round : plan_)
      for (const auto& stage : round.stages)
        for (const Part& part : stage) names.push_back(part.name);
    for (const auto& stage : stages) {
      std::size_t contexts = 0;
      for (const Part& part : stage) {
        contexts += part.has_context;
        if (std::find(names.begin(), names.end(), part.name) != names.end())
          throw std::logic_error("two parts called '" + part.name + "'");
        names.push_back(part.name);
      }
      if (contexts > 1) throw std::logic_error("a stage with parts '" + stage.front().name + "'... has two contexts");
    }
    plan_.push_back({repeats, std::move(stages)});
  }

  StageAt stage_at(std::uint32_t stage) const {
    std::uint32_t first = 0;
    for (const auto& round : plan_) {
      const auto size = std::uint32_t(round.stages.size());
      if (stage < first + round.repeats * size) {
        const std::uint32_t offset = stage - first;
        return {round.stages[offset % size], offset / size};
      }
      first += round.repeats * size;
    }
    throw RunError("stage " + std::to_string(stage) + " is past the job's " + std::to_string(first) + " stages");
  }

  Place place(WorkItemId id) const {
    const auto [parts, step] = stage_at(id.stage);
    std::uint64_t first = 0;
    for (const Part& part : parts) {
      const std::uint64_t count = part.items(step);
      if (id.item < first + count) return {part, {id, step, id.item - first}};
      first += count;
    }
    throw RunError("item " + std::to_string(id.item) + " is past the " + std::to_string(first) + " items of stage " +
                   std::to_string(id.stage));
  }

  // With an index, the item's id; without, the stage's number (item 0).
  WorkItemId find_part(std::string_view name, std::uint32_t step, std::optional<std::uint64_t> index) const {
    std::uint32_t first = 0;
    for (const auto& round : plan_) {
      const auto size = std::uint32_t(round.stages.size());
      for (std::uint32_t s = 0; s < size; ++s) {
        const auto& parts = round.stages[s];
        const auto found = std::find_if(parts.begin(), parts.end(), [&](const Part& p) { return p.name == name; });
        if (found == parts.end()) continue;
        if (step >= round.repeats)
          throw std::logic_error("step " + std::to_string(step) + " of '" + found->name + "' is past its " +
                                 std::to_string(round.repeats));
        std::uint64_t item = 0;
        if (index) {
          for (auto before = parts.begin(); before != found; ++before) item += before->items(step);
          item += *index;
        }
        return {first + step * size + s, item};
      }
      first += round.repeats * size;
    }
    throw std::logic_error("no part '" + std::string(name) + "' in the plan");
  }
  WorkItemId locate(std::string_view part, std::uint32_t step, std::uint64_t index) const override {
    return find_part(part, step, index);
  }

  std::vector<Round> plan_;
};

}  // namespace pbrfit::runtime
