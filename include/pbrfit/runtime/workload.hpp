#pragma once
// What the runtime needs of a job kind. Work is a sequence of stages (one for a LUT; one per level of a
// hierarchical sweep; one per migration epoch of island GP); the items of a stage are independent and
// are handed out dynamically to whichever rank and thread is free. A stage starts only when every item
// of the stages before it has finished and been collected.
//
// Contract (it is what makes results independent of ranks, threads, arrival order and interruptions):
//  - compute() is a pure function of (job text, ItemTask); it runs concurrently on many threads of many
//    ranks, so it may only read the workload. Read-only data the workload loads (tables, images,
//    datasets) exists once per process and is shared by its threads;
//  - stage_context() and item_input() run on rank 0 and read only results of earlier stages that
//    kept_through() still keeps;
//  - blocks() places a result at positions fixed by its item id (growing tables: in item order);
//  - fold_summary() combines results into the running summary behind headline(), in any order.
#include <atomic>
#include <cstdint>
#include <cstring>
#include <exception>
#include <string>
#include <type_traits>
#include <vector>

#include "pbrfit/core/bytes.hpp"
#include "pbrfit/core/item_results.hpp"
#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/store/result_layout.hpp"

namespace pbrfit::runtime {

// Thrown by compute() to give up on an item once stop_requested(): the item is neither done nor failed.
struct Cancelled : std::exception {
  const char* what() const noexcept override { return "cancelled"; }
};

// One work item as compute() sees it.
struct ItemTask {
  WorkItemId id;
  const Bytes& context;  // the stage's context, shared by all its items
  const Bytes& input;    // this item's own input
  std::uint64_t seed;    // the job's seed
  const std::atomic<bool>* cancelled = nullptr;  // set when the job stops; long computations may give up

  // The stream (job seed, stage, item, substream): the only source of random numbers a kind may use.
  RandomStream random(std::uint64_t substream = 0) const { return {seed, id.stage, id.item, substream}; }
  bool stop_requested() const { return cancelled && cancelled->load(std::memory_order_relaxed); }
};

class Workload {
 public:
  virtual ~Workload() = default;

  virtual store::ResultLayout layout() const = 0;
  virtual std::uint32_t stage_count() const { return 1; }
  virtual std::uint64_t item_count(std::uint32_t stage) const = 0;

  // What every item of a stage needs, sent once to every rank (over a tree: no rank sends it more than
  // log2(ranks) times). `kept` holds the results of earlier stages that kept_through() still keeps.
  virtual Bytes stage_context(std::uint32_t /*stage*/, const ItemResults& /*kept*/) const { return {}; }
  // What only one item needs (an island's population, a cell's parents), sent with the item.
  virtual Bytes item_input(std::uint32_t /*stage*/, std::uint64_t /*item*/, const ItemResults& /*kept*/) const {
    return {};
  }
  virtual Bytes compute(const ItemTask& task) const = 0;
  virtual std::vector<store::Block> blocks(WorkItemId id, const Bytes& result) const = 0;

  // The stage to run after `completed`, from the results kept so far (a search that has reached its target
  // goes straight to its last stage). Must be > completed and <= stage_count(), and a pure function of its
  // arguments. The items of the stages skipped count as done and produce nothing; results the stage after
  // `completed` would have kept stay kept into the stage run instead. Default: the next stage.
  virtual std::uint32_t next_stage(std::uint32_t completed, const ItemResults& /*kept*/) const { return completed + 1; }

  // The last stage whose context or inputs read this result. Until that stage is complete the result is
  // kept in rank 0's memory and in the checkpoint; after it, only its blocks remain (in the result file
  // and the block journal). Default: no later stage reads it.
  virtual std::uint32_t kept_through(WorkItemId id) const { return id.stage; }

  // The running summary behind the headline: folds one result in. The fold must give the same summary
  // in any order of results (maxima, counts, sums of integers), as results arrive in any order.
  virtual void fold_summary(Bytes& /*summary*/, WorkItemId /*id*/, const Bytes& /*result*/) const {}
  // One line for progress logs and `pbrfit status`, from the summary.
  virtual std::string headline(const Bytes& summary) const = 0;
  // A count of work the summary holds (e.g. program evaluations) and its unit; with a unit the progress
  // line also reports its rate ("1.2e+06 evaluations/s"). Default: none.
  virtual double work_done(const Bytes& /*summary*/) const { return 0.0; }
  virtual std::string work_unit() const { return {}; }

  std::uint64_t total_items() const;
};

// A summary kept as one trivially copyable struct; empty bytes read as a value-initialized T.
template <class T>
T summary_as(const Bytes& bytes) {
  static_assert(std::is_trivially_copyable_v<T>);
  T value{};
  if (bytes.size() == sizeof(T)) std::memcpy(&value, bytes.data(), sizeof(T));
  return value;
}

template <class T>
void store_summary(Bytes& bytes, const T& value) {
  static_assert(std::is_trivially_copyable_v<T>);
  bytes.resize(sizeof(T));
  std::memcpy(bytes.data(), &value, sizeof(T));
}

}  // namespace pbrfit::runtime
