#include "run_state.hpp"

#include <limits>
#include <stdexcept>

namespace pbrfit::runtime {

namespace {

constexpr std::uint32_t not_growing = std::numeric_limits<std::uint32_t>::max();

}  // namespace

RunState::RunState(const Workload& workload, const store::BlockCodec& codec) : workload_(workload), codec_(codec) {
  const auto& tables = codec.tables();
  for (std::uint32_t t = 0; t < tables.size(); ++t) {
    growing_slot_.push_back(tables.table(t).growing ? std::uint32_t(rows_.size()) : not_growing);
    if (tables.table(t).growing) rows_.push_back(0);
  }
  start_stage(0);
}

RunState::RunState(const Workload& workload, const store::BlockCodec& codec, store::CheckpointState saved)
    : RunState(workload, codec) {
  for (std::uint32_t s = 0; s < saved.stage; ++s) done_before_ += workload.item_count(s);
  start_stage(saved.stage);
  summary_ = std::move(saved.summary);
  rows_ = std::move(saved.rows);
  for (auto& [id, result] : saved.retained) (id.stage < stage_ ? kept_ : kept_now_)[id] = std::move(result);
  for (const auto item : saved.done) {
    done_[item] = true;
    ++done_count_;
  }
  appends_ = std::move(saved.appends);
  needs_snapshot_ = false;
}

void RunState::start_stage(std::uint32_t stage) {
  stage_ = stage;
  done_.assign(finished() ? 0 : workload_.item_count(stage), false);
  done_count_ = 0;
}

void RunState::add_blocks(const std::vector<store::Block>& blocks, Bytes& appends) {
  ByteWriter growing;
  std::uint64_t growing_count = 0;
  for (const auto& block : blocks) {
    if (growing_slot_[codec_.tables().find(block.group, block.table)] != not_growing) {
      codec_.encode(growing, block);
      ++growing_count;
    } else {
      PendingBlocks::add_to_both(codec_, block, unflushed_, unjournaled_);
    }
  }
  if (growing_count == 0) return;
  ByteWriter out;
  out.put(growing_count);
  appends = out.take();
  appends.insert(appends.end(), growing.bytes().begin(), growing.bytes().end());
}

void RunState::accept(std::uint64_t item, Bytes result) {
  if (item >= done_.size() || done_[item])
    throw std::logic_error("result for item " + std::to_string(item) + " of stage " + std::to_string(stage_) +
                           ", which is not outstanding");
  const WorkItemId id{stage_, item};
  Bytes appends;
  add_blocks(workload_.blocks(id, result), appends);
  if (!appends.empty()) appends_[item] = std::move(appends);
  workload_.fold_summary(summary_, id, result);
  if (workload_.kept_through(id) > stage_) kept_now_[id] = std::move(result);
  done_[item] = true;
  ++done_count_;
  new_items_.push_back(item);
}

void RunState::place_growing_rows() {
  for (const auto& [item, encoded] : appends_) {
    ByteReader in(encoded);
    const auto count = in.get<std::uint64_t>();
    std::vector<std::uint64_t> used(rows_.size(), 0);
    for (std::uint64_t i = 0; i < count; ++i) {
      store::Block block = codec_.decode(in);
      const std::uint32_t slot = growing_slot_[codec_.tables().find(block.group, block.table)];
      used[slot] = std::max(used[slot], block.offset[0] + block.count[0]);
      block.offset[0] += rows_[slot];
      PendingBlocks::add_to_both(codec_, block, unflushed_, unjournaled_);
    }
    for (std::size_t s = 0; s < rows_.size(); ++s) rows_[s] += used[s];
  }
  appends_.clear();
}

void RunState::advance() {
  if (!stage_complete())
    throw std::logic_error("stage " + std::to_string(stage_) + " ended with " + std::to_string(done_count_) + " of " +
                           std::to_string(done_.size()) + " items done");
  place_growing_rows();
  kept_.merge(kept_now_);
  kept_now_.clear();
  done_before_ += done_.size();
  const std::uint32_t completed = stage_, next = workload_.next_stage(completed, kept_);
  if (next <= completed || next > workload_.stage_count())
    throw std::logic_error("next_stage(" + std::to_string(completed) + ") gave " + std::to_string(next));
  for (std::uint32_t skipped = completed + 1; skipped < next; ++skipped) done_before_ += workload_.item_count(skipped);
  start_stage(next);
  std::erase_if(kept_, [&](const auto& entry) { return workload_.kept_through(entry.first) <= completed; });
  new_items_.clear();
  needs_snapshot_ = true;
}

std::vector<store::Block> RunState::take_unflushed() {
  auto blocks = unflushed_.decode(codec_);
  unflushed_.clear();
  return blocks;
}

store::CheckpointState RunState::snapshot(const std::string& job_text, double elapsed, std::uint64_t journal_length) const {
  store::CheckpointState s;
  s.job_text = job_text;
  s.stage = stage_;
  s.elapsed_seconds = elapsed;
  s.summary = summary_;
  s.rows = rows_;
  s.journal_length = journal_length;
  s.retained = kept_;
  for (const auto& [id, result] : kept_now_) s.retained[id] = result;
  for (std::uint64_t item = 0; item < done_.size(); ++item)
    if (done_[item]) s.done.push_back(item);
  s.appends = appends_;
  return s;
}

store::CheckpointProgress RunState::progress(double elapsed, std::uint64_t journal_length) const {
  store::CheckpointProgress p{elapsed, summary_, rows_, journal_length, {}};
  for (const auto item : new_items_) {
    store::FinishedItem f{item, std::nullopt, {}};
    if (const auto kept = kept_now_.find({stage_, item}); kept != kept_now_.end()) f.retained = kept->second;
    if (const auto appends = appends_.find(item); appends != appends_.end()) f.appends = appends->second;
    p.finished.push_back(std::move(f));
  }
  return p;
}

void RunState::saved() {
  new_items_.clear();
  needs_snapshot_ = false;
}

}  // namespace pbrfit::runtime
