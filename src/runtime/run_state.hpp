#pragma once
// Rank 0's account of a job: the stage in progress and which of its items are done, the results that
// later stages still read, the running summary, the rows used in each growing table, and the encoded
// blocks waiting for the result file and for the block journal. Private to the runtime.
//
// Invariants:
//  - every stage before stage() is complete (advance() refuses an incomplete stage);
//  - kept() holds only results of earlier stages, and only those kept_through() still keeps, so a stage
//    context or item input never sees a result of its own stage;
//  - a block is in the journal buffer until the checkpointer has made it durable; growing-table blocks
//    wait with their item until the stage ends, then get their rows in item order.
#include <cstdint>
#include <map>
#include <vector>

#include "pbrfit/runtime/workload.hpp"
#include "pbrfit/store/checkpoint_file.hpp"
#include "pending_blocks.hpp"

namespace pbrfit::runtime {

class RunState {
 public:
  // A job from its beginning.
  RunState(const Workload& workload, const store::BlockCodec& codec);
  // A job continued from a checkpoint that check_checkpoint() accepted.
  RunState(const Workload& workload, const store::BlockCodec& codec, store::CheckpointState saved);

  std::uint32_t stage() const { return stage_; }
  bool finished() const { return stage_ >= workload_.stage_count(); }
  bool stage_complete() const { return done_count_ == done_.size(); }
  bool done(std::uint64_t item) const { return done_[item]; }
  std::uint64_t items_done() const { return done_before_ + done_count_; }
  const ItemResults& kept() const { return kept_; }
  const Bytes& summary() const { return summary_; }

  void accept(std::uint64_t item, Bytes result);
  // Ends the complete current stage and starts the next.
  void advance();

  std::vector<store::Block> take_unflushed();
  std::uint64_t unflushed_blocks() const { return unflushed_.count(); }
  const PendingBlocks& unjournaled() const { return unjournaled_; }
  void journaled() { unjournaled_.clear(); }

  // The checkpoint record to write next: a whole snapshot once the stage has changed since the last one,
  // else the progress since the last checkpoint. Call saved() once it is durable.
  bool needs_snapshot() const { return needs_snapshot_; }
  store::CheckpointState snapshot(const std::string& job_text, double elapsed, std::uint64_t journal_length) const;
  store::CheckpointProgress progress(double elapsed, std::uint64_t journal_length) const;
  bool has_news() const { return needs_snapshot_ || !new_items_.empty(); }
  void saved();

 private:
  void start_stage(std::uint32_t stage);
  void place_growing_rows();
  void add_blocks(const std::vector<store::Block>& blocks, Bytes& appends);

  const Workload& workload_;
  const store::BlockCodec& codec_;
  std::vector<std::uint32_t> growing_slot_;  // by table index; rows_ index or UINT32_MAX
  std::uint32_t stage_ = 0;
  std::uint64_t done_before_ = 0;            // items of earlier stages
  std::vector<bool> done_;                   // items of this stage
  std::uint64_t done_count_ = 0;
  ItemResults kept_, kept_now_;              // earlier stages' / this stage's kept results
  std::map<std::uint64_t, Bytes> appends_;   // encoded growing-table blocks of this stage's done items
  std::vector<std::uint64_t> rows_;          // per growing table
  Bytes summary_;
  PendingBlocks unflushed_, unjournaled_;
  std::vector<std::uint64_t> new_items_;     // done since the last checkpoint
  bool needs_snapshot_ = true;
};

}  // namespace pbrfit::runtime
