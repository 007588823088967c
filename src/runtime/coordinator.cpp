#include "coordinator.hpp"

#include <spdlog/spdlog.h>

#include <numeric>
#include <thread>

#include "duration_text.hpp"
#include "pbrfit/core/error.hpp"
#include "pbrfit/runtime/stop_signal.hpp"
#include "relay_tree.hpp"

namespace pbrfit::runtime {

namespace {

// Finished blocks wait in memory, encoded, for the next flush and the next checkpoint; beyond these
// amounts the flush or checkpoint comes early, whatever the intervals, so rank 0's memory stays bounded.
constexpr std::size_t max_unflushed_blocks = 65536;
constexpr std::size_t max_unjournaled_bytes = std::size_t(32) << 20;

}  // namespace

Coordinator::Coordinator(const MpiSession& mpi, const Workload& workload, const RunSettings& settings, RunState& state,
                         Checkpointer& checkpointer, store::ResultFile& file, std::vector<int> threads,
                         double elapsed_before)
    : mpi_(mpi),
      workload_(workload),
      settings_(settings),
      state_(state),
      checkpointer_(checkpointer),
      file_(file),
      threads_(std::move(threads)),
      depth_(threads_),
      pool_(workload, settings.seed, threads_[0]),
      sent_(std::size_t(mpi.size()), 0),
      said_bye_(std::size_t(mpi.size()), false),
      items_total_(workload.total_items()),
      done_at_start_(state.items_done()),
      elapsed_before_(elapsed_before) {}

double Coordinator::elapsed() const {
  return elapsed_before_ + std::chrono::duration<double>(Clock::now() - started_).count();
}

Outcome Coordinator::run() {
  if (done_at_start_ > 0) spdlog::info("resuming: {} of {} work items already done", done_at_start_, items_total_);
  try {
    while (!state_.finished() && !stopping()) {
      begin_stage();
      run_stage();
      if (!stopping()) state_.advance();
    }
  } catch (const std::exception& e) {
    if (!failure_) failure_ = e.what();
  }
  stop_workers();
  if (failure_) spdlog::error("job failed: {}", *failure_);
  Outcome outcome = failure_ ? Outcome::failed : interrupted_ ? Outcome::interrupted : Outcome::complete;
  try {
    finish(outcome);
  } catch (const std::exception& e) {
    spdlog::error("cannot save the outcome: {}", e.what());
    outcome = Outcome::failed;
  }
  return outcome;
}

// The context is built from kept results of earlier stages only: RunState::advance() refused to leave
// the previous stage before every one of its results had been collected.
void Coordinator::begin_stage() {
  const std::uint32_t stage = state_.stage();
  ByteWriter header;
  header.put(stage);
  header.put_bytes(workload_.stage_context(stage, state_.kept()));
  context_ = std::make_shared<const Bytes>(header.take());
  for (int child : relay_children(0, mpi_.size())) outbox_.send(child, Tag::stage, context_);
  // The context the compute threads see starts after the stage number and the length.
  context_ = std::make_shared<const Bytes>(context_->begin() + sizeof(std::uint32_t) + sizeof(std::uint64_t), context_->end());
  todo_.clear();
  for (std::uint64_t item = 0; item < workload_.item_count(stage); ++item)
    if (!state_.done(item)) todo_.push_back(item);
  if (workload_.stage_count() > 1)
    spdlog::info("stage {} of {}: {} work items", stage + 1, workload_.stage_count(), workload_.item_count(stage));
}

void Coordinator::run_stage() {
  while (!todo_.empty() || pool_.outstanding() > 0 || std::accumulate(sent_.begin(), sent_.end(), std::size_t{0}) > 0) {
    check_stop_signal();
    if (auto failure = pool_.failure(); failure && !failure_) failure_ = "rank 0 failed on " + *failure;
    if (stopping()) return;
    dispatch();
    const bool busy = poll();
    outbox_.progress();
    maybe_checkpoint();
    maybe_flush();
    maybe_log_progress();
    const auto pause = backoff_.next(busy);
    if (!busy) pool_.wait(pause);
  }
}

void Coordinator::check_stop_signal() {
  if (!stop_requested() || interrupted_) return;
  spdlog::warn("{} received: stopping at the next safe point", stop_signal_name());
  interrupted_ = true;
}

void Coordinator::dispatch() {
  const std::uint32_t stage = state_.stage();
  depth_.update(Clock::now());
  while (!todo_.empty() && pool_.outstanding() < depth_.for_rank(0, todo_.size())) {
    pool_.assign({stage, todo_.front()}, context_, workload_.item_input(stage, todo_.front(), state_.kept()));
    todo_.pop_front();
  }
  for (int r = 1; r < mpi_.size(); ++r) {
    while (!todo_.empty() && sent_[std::size_t(r)] < depth_.for_rank(r, todo_.size())) {
      ByteWriter work;
      work.put(stage);
      work.put(todo_.front());
      work.put_bytes(workload_.item_input(stage, todo_.front(), state_.kept()));
      outbox_.send(r, Tag::work, work.take());
      todo_.pop_front();
      ++sent_[std::size_t(r)];
    }
  }
}

bool Coordinator::poll() {
  bool busy = false;
  for (auto& finished : pool_.take_finished()) {
    accept(finished.id, std::move(finished.result));
    depth_.finished(0);
    busy = true;
  }
  while (auto message = try_receive()) {
    handle(*message);
    busy = true;
  }
  return busy;
}

void Coordinator::handle(Message& message) {
  ByteReader in(message.payload);
  const auto source = std::size_t(message.source);
  switch (message.tag) {
    case Tag::result: {
      const WorkItemId id{in.get<std::uint32_t>(), in.get<std::uint64_t>()};
      --sent_[source];
      accept(id, in.get_bytes());
      depth_.finished(message.source);
      break;
    }
    case Tag::failed:
      if (!failure_) failure_ = "rank " + std::to_string(message.source) + " failed on " + in.get_string();
      break;
    case Tag::signalled:
      if (!interrupted_) spdlog::warn("rank {} received a stop signal: stopping at the next safe point", message.source);
      interrupted_ = true;
      break;
    case Tag::bye:
      said_bye_[source] = true;
      break;
    default:
      throw RunError("unexpected message from rank " + std::to_string(message.source));
  }
}

void Coordinator::accept(WorkItemId id, Bytes result) {
  if (id.stage != state_.stage()) throw std::logic_error("a result of stage " + std::to_string(id.stage) + " arrived in stage " + std::to_string(state_.stage()));
  state_.accept(id.item, std::move(result));
  ++done_since_checkpoint_;
}

// Waits for the other ranks' last results and their bye, at most stop_grace_seconds: a rank that died or
// hangs must not keep the checkpoint from being written.
void Coordinator::stop_workers() {
  pool_.stop();
  for (auto& finished : pool_.take_finished()) accept(finished.id, std::move(finished.result));
  for (int r = 1; r < mpi_.size(); ++r) outbox_.send(r, Tag::stop);
  const auto deadline = Clock::now() + std::chrono::duration<double>(settings_.stop_grace_seconds);
  while (std::count(said_bye_.begin() + 1, said_bye_.end(), false) > 0 && Clock::now() < deadline) {
    outbox_.progress();
    if (auto message = try_receive()) {
      try {
        handle(*message);
      } catch (const std::exception& e) {
        if (!failure_) failure_ = e.what();
      }
    } else {
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
  }
  for (int r = 1; r < mpi_.size(); ++r)
    if (!said_bye_[std::size_t(r)]) spdlog::error("rank {} did not answer within {} s of the stop", r, settings_.stop_grace_seconds);
}

void Coordinator::finish(Outcome outcome) {
  if (outcome == Outcome::complete) {
    flush("complete");
    file_.sync_to_disk();
    checkpointer_.remove_files();
    spdlog::info("done: {} work items in {} ({} this run); {}", items_total_, duration_text(elapsed()),
                 duration_text(std::chrono::duration<double>(Clock::now() - started_).count()),
                 workload_.headline(state_.summary()));
    return;
  }
  save_checkpoint();
  flush(outcome == Outcome::failed ? "failed" : "interrupted");
}

void Coordinator::say_farewell(int code) {
  ByteWriter out;
  out.put<std::int32_t>(code);
  for (int r = 1; r < mpi_.size(); ++r)
    if (said_bye_[std::size_t(r)]) outbox_.send(r, Tag::farewell, out.bytes());
  outbox_.drain(std::chrono::milliseconds(2000));
}

void Coordinator::save_checkpoint() {
  const auto before = checkpointer_.bytes_written();
  checkpointer_.save(state_, elapsed());
  done_since_checkpoint_ = 0;
  last_checkpoint_ = Clock::now();
  spdlog::debug("checkpoint written: {} of {} items; {} bytes written, checkpoint {} bytes, journal {} bytes",
                state_.items_done(), items_total_, checkpointer_.bytes_written() - before,
                checkpointer_.checkpoint_bytes(), checkpointer_.journal_bytes());
}

void Coordinator::maybe_checkpoint() {
  const double since = std::chrono::duration<double>(Clock::now() - last_checkpoint_).count();
  const bool by_time = settings_.checkpoint_interval_seconds > 0 && since >= settings_.checkpoint_interval_seconds;
  const bool by_items = settings_.checkpoint_interval_items > 0 &&
                        done_since_checkpoint_ >= std::uint64_t(settings_.checkpoint_interval_items);
  const bool by_memory = state_.unjournaled().bytes().size() >= max_unjournaled_bytes;
  if ((by_time || by_items || by_memory) && state_.has_news()) save_checkpoint();
}

void Coordinator::maybe_flush() {
  const bool by_time =
      std::chrono::duration<double>(Clock::now() - last_flush_).count() >= settings_.flush_interval_seconds;
  if (by_time || state_.unflushed_blocks() >= max_unflushed_blocks) flush("running");
}

void Coordinator::flush(const std::string& state) {
  file_.write(state_.take_unflushed(), progress(state));
  last_flush_ = Clock::now();
}

store::Progress Coordinator::progress(const std::string& state) const {
  store::Progress p;
  p.state = state;
  p.items_done = state_.items_done();
  p.items_total = items_total_;
  p.elapsed_seconds = elapsed();
  p.headline = workload_.headline(state_.summary());
  if (state != "running") p.finished_utc = store::utc_now_iso8601();
  return p;
}

void Coordinator::maybe_log_progress() {
  const auto now = Clock::now();
  if (std::chrono::duration<double>(now - last_progress_).count() < settings_.progress_interval_seconds) return;
  last_progress_ = now;
  const auto done = state_.items_done();
  const double run_seconds = std::chrono::duration<double>(now - started_).count();
  const double rate = double(done - done_at_start_) / std::max(run_seconds, 1e-9);
  const double eta = rate > 0 ? double(items_total_ - done) / rate : 0.0;
  spdlog::info("{:5.1f}% ({}/{} items, {:.1f} items/s, ETA {}) {}", 100.0 * double(done) / double(items_total_), done,
               items_total_, rate, rate > 0 ? duration_text(eta) : "unknown", workload_.headline(state_.summary()));
}

}  // namespace pbrfit::runtime
