#include "coordinator.hpp"

#include <spdlog/spdlog.h>

#include <numeric>

#include "pbrfit/core/error.hpp"
#include "pbrfit/runtime/stop_signal.hpp"
#include "relay_tree.hpp"

namespace pbrfit::runtime {

Coordinator::Coordinator(const MpiSession& mpi, const Workload& workload, const RunSettings& settings, RunState& state,
                         Persistence& persistence, std::vector<int> threads, double elapsed_before)
    : mpi_(mpi),
      workload_(workload),
      settings_(settings),
      state_(state),
      persistence_(persistence),
      threads_(std::move(threads)),
      depth_(threads_),
      peers_(mpi.size()),
      progress_(workload, settings.progress_interval_seconds, state.items_done()),
      pool_(workload, settings.seed, threads_[0]),
      sent_(std::size_t(mpi.size()), 0),
      said_bye_(std::size_t(mpi.size()), false),
      elapsed_before_(elapsed_before) {}

double Coordinator::elapsed() const {
  return elapsed_before_ + std::chrono::duration<double>(Clock::now() - started_).count();
}

Outcome Coordinator::run() {
  if (state_.items_done() > 0)
    spdlog::info("resuming: {} of {} work items already done", state_.items_done(), workload_.total_items());
  try {
    // Readers see a resumed run from its start: until this first publication its file still said how
    // the previous run ended, and a resume killed in its first second left it saying so. (A fresh run
    // publishes at its first flush; until then `status` reads its checkpoint.)
    if (!state_.finished() && state_.items_done() > 0)
      persistence_.write_and_publish(store::RunStatus::running, elapsed());
    while (!state_.finished() && !stopping()) {
      begin_stage();
      run_stage();
      spdlog::debug("{}", load_.stage_summary(workload_.item_count(state_.stage())));
      if (stopping()) break;
      state_.advance();
    }
  } catch (const std::exception& e) {
    if (!failure_) failure_ = e.what();
  }
  stop_everything();
  spdlog::debug("{}", load_.run_summary());
  if (failure_) spdlog::error("job failed: {}", *failure_);
  Outcome outcome = failure_     ? Outcome::failed
                    : lost_rank_ ? Outcome::lost_rank
                    : interrupted_ ? Outcome::interrupted
                                   : Outcome::complete;
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
  const auto message = std::make_shared<const Bytes>(header.take());
  for (int child : relay_children(0, mpi_.size())) outbox_.send(child, Tag::stage, message);
  ByteReader in(*message);
  in.get<std::uint32_t>();
  context_ = std::make_shared<const Bytes>(in.get_bytes());
  load_.begin_stage(stage);
  todo_.clear();
  for (std::uint64_t item = 0; item < workload_.item_count(stage); ++item)
    if (!state_.done(item)) todo_.push_back(item);
  if (workload_.stage_count() > 1)
    spdlog::info("stage {} of {}: {} work items", stage + 1, workload_.stage_count(), workload_.item_count(stage));
}

void Coordinator::run_stage() {
  while (!todo_.empty() || pool_.outstanding() > 0 || std::accumulate(sent_.begin(), sent_.end(), std::size_t{0}) > 0) {
    check_stop_signal();
    watch_peers();
    if (auto failure = pool_.failure(); failure && !failure_) failure_ = "rank 0 failed on " + *failure;
    if (stopping()) return;
    dispatch();
    const bool busy = poll();
    outbox_.progress();
    persistence_.tick(elapsed());
    progress_.maybe_log(state_);
    const auto pause = backoff_.next(busy, pool_.outstanding() == 0);
    if (!busy) pool_.wait(pause);
  }
}

void Coordinator::check_stop_signal() {
  if (!stop_requested() || interrupted_) return;
  spdlog::warn("{} received: stopping at the next safe point", stop_signal_origin());
  interrupted_ = true;
}

// Heartbeats keep the other ranks from taking rank 0 for lost; a rank silent for too long is lost.
void Coordinator::watch_peers() {
  if (heartbeat_.due()) {
    for (int r = 1; r < mpi_.size(); ++r) outbox_.send(r, Tag::heartbeat);
    heartbeat_.sent();
  }
  for (int r = 1; r < mpi_.size() && !lost_rank_; ++r) {
    if (peers_.silent_seconds(r) < settings_.rank_timeout_seconds) continue;
    spdlog::error("rank {} has sent nothing for {:.0f} s (it died or hangs): stopping; `pbrfit run JOB --resume` "
                  "continues", r, peers_.silent_seconds(r));
    lost_rank_ = r;
  }
}

void Coordinator::dispatch() {
  const std::uint32_t stage = state_.stage();
  depth_.update(Clock::now());
  while (!todo_.empty() && pool_.outstanding() < depth_.for_rank(0, todo_.size())) {
    pool_.assign({stage, todo_.front()}, context_, workload_.item_input(stage, todo_.front(), state_.kept()));
    todo_.pop_front();
  }
  // What a rank lacks goes in one message (or a few, when inputs are large).
  for (int r = 1; r < mpi_.size(); ++r) {
    auto& sent = sent_[std::size_t(r)];
    while (!todo_.empty() && sent < depth_.for_rank(r, todo_.size())) {
      ByteWriter work;
      work.put(stage);
      std::size_t items = 0;
      while (!todo_.empty() && sent < depth_.for_rank(r, todo_.size()) && work.bytes().size() < batch_bytes) {
        work.put(todo_.front());
        work.put_bytes(workload_.item_input(stage, todo_.front(), state_.kept()));
        todo_.pop_front();
        ++sent;
        ++items;
      }
      Bytes payload = work.take();
      load_.sent_work(payload.size(), items);
      outbox_.send(r, Tag::work, std::move(payload));
    }
  }
}

bool Coordinator::poll() {
  bool busy = false;
  for (auto& finished : pool_.take_finished()) {
    accept(finished.id, std::move(finished.result), finished.seconds);
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
  peers_.heard(message.source);
  switch (message.tag) {
    case Tag::result: {
      std::size_t items = 0;
      while (in.remaining() > 0) {
        const WorkItemId id{in.get<std::uint32_t>(), in.get<std::uint64_t>()};
        const auto seconds = in.get<double>();
        if (sent_[source] == 0) throw RunError("rank " + std::to_string(message.source) + " sent a result it was not asked for");
        --sent_[source];
        accept(id, in.get_bytes(), seconds);
        depth_.finished(message.source);
        ++items;
      }
      load_.received_results(message.payload.size(), items);
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
    case Tag::heartbeat:
      break;
    default:
      throw RunError("unexpected message from rank " + std::to_string(message.source));
  }
}

void Coordinator::accept(WorkItemId id, Bytes result, double seconds) {
  if (id.stage != state_.stage())
    throw std::logic_error("a result of stage " + std::to_string(id.stage) + " arrived in stage " +
                           std::to_string(state_.stage()));
  state_.accept(id.item, std::move(result));
  persistence_.finished_one();
  load_.item_done(seconds);
}

}  // namespace pbrfit::runtime
