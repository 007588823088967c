#include "coordinator.hpp"

#include <spdlog/spdlog.h>

#include <thread>

#include "messages.hpp"
#include "pbrfit/core/error.hpp"
#include "pbrfit/runtime/stop_signal.hpp"

namespace pbrfit::runtime {

namespace {

std::string format_duration(double seconds) {
  char text[32];
  if (seconds < 60) std::snprintf(text, sizeof text, "%.1fs", seconds);
  else if (seconds < 3600) std::snprintf(text, sizeof text, "%dm%02ds", int(seconds) / 60, int(seconds) % 60);
  else std::snprintf(text, sizeof text, "%dh%02dm", int(seconds) / 3600, int(seconds) % 3600 / 60);
  return text;
}

}  // namespace

Coordinator::Coordinator(const MpiSession& mpi, const Workload& workload, const RunSettings& settings,
                         store::Checkpoint resumed, store::ResultFile& file)
    : mpi_(mpi),
      workload_(workload),
      settings_(settings),
      file_(file),
      checkpoint_(std::move(resumed)),
      local_(workload),
      remote_outstanding_(std::size_t(mpi.size()), 0),
      total_items_(workload.total_items()),
      done_at_start_(checkpoint_.results.size()),
      elapsed_before_(checkpoint_.elapsed_seconds) {
  for (const auto& [id, result] : checkpoint_.results) file_.add(workload_.blocks(id, result));
}

double Coordinator::elapsed() const {
  return elapsed_before_ + std::chrono::duration<double>(Clock::now() - started_).count();
}

std::size_t Coordinator::outstanding() const {
  std::size_t n = local_.outstanding();
  for (std::size_t r = 1; r < remote_outstanding_.size(); ++r) n += remote_outstanding_[r];
  return n;
}

store::Progress Coordinator::progress(const std::string& state) const {
  store::Progress p;
  p.state = state;
  p.items_done = checkpoint_.results.size();
  p.items_total = total_items_;
  p.elapsed_seconds = elapsed();
  p.headline = workload_.headline(checkpoint_.results);
  if (state != "running") p.finished_utc = store::utc_now_iso8601();
  return p;
}

Outcome Coordinator::run() {
  if (done_at_start_ > 0)
    spdlog::info("resuming: {} of {} work items already done", done_at_start_, total_items_);
  try {
    for (std::uint32_t stage = checkpoint_.stage; stage < workload_.stage_count(); ++stage) {
      checkpoint_.stage = stage;
      run_stage(stage);
      if (failure_ || interrupted_) break;
    }
  } catch (const std::exception& e) {
    if (!failure_) failure_ = e.what();
  }
  stop_all_workers();
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

void Coordinator::finish(Outcome outcome) {
  const char* state = outcome == Outcome::complete ? "complete" : outcome == Outcome::failed ? "failed" : "interrupted";
  if (outcome != Outcome::complete) write_checkpoint();
  const auto final_progress = progress(state);
  file_.flush(final_progress);
  if (outcome != Outcome::complete) return;
  std::remove(store::checkpoint_path_for(settings_.output).c_str());
  spdlog::info("done: {} work items in {} ({} this run); {}", total_items_, format_duration(elapsed()),
               format_duration(std::chrono::duration<double>(Clock::now() - started_).count()),
               final_progress.headline);
}

void Coordinator::run_stage(std::uint32_t stage) {
  context_ = workload_.stage_context(stage, checkpoint_.results);
  local_.set_context(&context_);
  ByteWriter header;
  header.put(stage);
  header.put_bytes(context_);
  for (int r = 1; r < mpi_.size(); ++r) send(r, Tag::stage, header.bytes());

  std::deque<std::uint64_t> todo;
  for (std::uint64_t item = 0; item < workload_.item_count(stage); ++item)
    if (!checkpoint_.results.contains({stage, item})) todo.push_back(item);

  while (!todo.empty() || outstanding() > 0) {
    if (stop_requested() && !interrupted_) {
      spdlog::warn("{} received: stopping at the next safe point", stop_signal_name());
      interrupted_ = true;
    }
    if (auto failure = local_.failure(); failure && !failure_) {
      failure_ = "rank 0 failed on " + *failure;
    }
    if (failure_ || interrupted_) return;
    dispatch(todo, stage);
    const bool busy = poll();
    try {
      maybe_checkpoint();
      maybe_flush();
    } catch (const RunError& e) {
      failure_ = e.what();
    }
    maybe_log_progress();
    if (!busy) std::this_thread::sleep_for(std::chrono::microseconds(1000));
  }
}

void Coordinator::dispatch(std::deque<std::uint64_t>& todo, std::uint32_t stage) {
  // Two items per rank hide the round trip to the coordinator; near the end one item each keeps the
  // last items from queueing behind a busy rank while another is idle.
  const std::size_t depth = todo.size() > std::size_t(2 * mpi_.size()) ? 2 : 1;
  while (!todo.empty() && local_.outstanding() < depth) {
    local_.assign({stage, todo.front()});
    todo.pop_front();
  }
  for (int r = 1; r < mpi_.size(); ++r) {
    while (!todo.empty() && remote_outstanding_[std::size_t(r)] < depth) {
      ByteWriter item;
      item.put(todo.front());
      send(r, Tag::work, item.bytes());
      todo.pop_front();
      ++remote_outstanding_[std::size_t(r)];
    }
  }
}

bool Coordinator::poll() {
  bool busy = false;
  for (auto& [id, result] : local_.take_results()) {
    accept(id, std::move(result));
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
  switch (message.tag) {
    case Tag::result: {
      WorkItemId id;
      id.stage = in.get<std::uint32_t>();
      id.item = in.get<std::uint64_t>();
      --remote_outstanding_[std::size_t(message.source)];
      accept(id, in.get_bytes());
      break;
    }
    case Tag::failed:
      if (!failure_) failure_ = "rank " + std::to_string(message.source) + " failed on " + in.get_string();
      break;
    case Tag::signalled:
      if (!interrupted_) spdlog::warn("rank {} received a stop signal: stopping at the next safe point", message.source);
      interrupted_ = true;
      break;
    default:
      throw RunError("unexpected message from rank " + std::to_string(message.source));
  }
}

void Coordinator::accept(WorkItemId id, Bytes result) {
  file_.add(workload_.blocks(id, result));
  checkpoint_.results[id] = std::move(result);
  ++done_since_checkpoint_;
}

void Coordinator::stop_all_workers() {
  local_.stop();
  for (auto& [id, result] : local_.take_results()) accept(id, std::move(result));
  int waiting = mpi_.size() - 1;
  for (int r = 1; r < mpi_.size(); ++r) send(r, Tag::stop);
  while (waiting > 0) {
    Message message = receive();
    if (message.tag == Tag::bye) --waiting;
    else if (message.tag != Tag::signalled) handle(message);
  }
}

void Coordinator::write_checkpoint() {
  checkpoint_.job_text = settings_.job_text;
  checkpoint_.elapsed_seconds = elapsed();
  store::write_checkpoint(store::checkpoint_path_for(settings_.output), checkpoint_);
  done_since_checkpoint_ = 0;
  last_checkpoint_ = Clock::now();
  spdlog::debug("checkpoint written: {} of {} items", checkpoint_.results.size(), total_items_);
}

void Coordinator::maybe_checkpoint() {
  const double since = std::chrono::duration<double>(Clock::now() - last_checkpoint_).count();
  const bool by_time = settings_.checkpoint_interval_seconds > 0 && since >= settings_.checkpoint_interval_seconds;
  const bool by_items = settings_.checkpoint_interval_items > 0 &&
                        done_since_checkpoint_ >= std::uint64_t(settings_.checkpoint_interval_items);
  if ((by_time || by_items) && done_since_checkpoint_ > 0) write_checkpoint();
}

void Coordinator::maybe_flush() {
  const double since = std::chrono::duration<double>(Clock::now() - last_flush_).count();
  if (since < settings_.flush_interval_seconds) return;
  file_.flush(progress("running"));
  last_flush_ = Clock::now();
}

void Coordinator::maybe_log_progress() {
  const auto now = Clock::now();
  if (std::chrono::duration<double>(now - last_progress_).count() < settings_.progress_interval_seconds) return;
  last_progress_ = now;
  const auto done = checkpoint_.results.size();
  const double run_seconds = std::chrono::duration<double>(now - started_).count();
  const double rate = double(done - done_at_start_) / std::max(run_seconds, 1e-9);
  const double eta = rate > 0 ? double(total_items_ - done) / rate : 0.0;
  spdlog::info("{:5.1f}% ({}/{} items, {:.1f} items/s, ETA {}) {}", 100.0 * double(done) / double(total_items_),
               done, total_items_, rate, rate > 0 ? format_duration(eta) : "unknown",
               workload_.headline(checkpoint_.results));
}

}  // namespace pbrfit::runtime
