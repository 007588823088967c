#include "persistence.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>

namespace pbrfit::runtime {

namespace {

// Finished blocks wait in memory, encoded, for the next write and the next checkpoint; beyond these
// amounts the write or checkpoint comes early, whatever the intervals, so rank 0's memory stays bounded.
constexpr std::uint64_t max_unwritten_blocks = 65536;
constexpr std::size_t max_unjournaled_bytes = std::size_t(32) << 20;

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

Persistence::Persistence(const RunSettings& settings, const Workload& workload, RunState& state,
                         Checkpointer& checkpointer, store::ResultFile& file)
    : settings_(settings),
      workload_(workload),
      state_(state),
      checkpointer_(checkpointer),
      file_(file),
      items_total_(workload.total_items()),
      pacing_(settings.flush_interval_seconds) {}

store::Progress Persistence::progress(store::RunStatus state, double elapsed) const {
  store::Progress p;
  p.state = state;
  p.items_done = state_.items_done();
  p.items_total = items_total_;
  p.elapsed_seconds = elapsed;
  p.headline = workload_.headline(state_.summary());
  if (state != store::RunStatus::running) p.finished_utc = store::utc_now_iso8601();
  return p;
}

void Persistence::tick(double elapsed) {
  const bool checkpoint_by_time = settings_.checkpoint_interval_seconds > 0 &&
                                  seconds_since(last_checkpoint_) >= settings_.checkpoint_interval_seconds;
  const bool checkpoint_by_items = settings_.checkpoint_interval_items > 0 &&
                                   finished_since_checkpoint_ >= std::uint64_t(settings_.checkpoint_interval_items);
  const bool checkpoint_by_memory = state_.unjournaled().bytes().size() >= max_unjournaled_bytes;
  if ((checkpoint_by_time || checkpoint_by_items || checkpoint_by_memory) && state_.has_news()) save_checkpoint(elapsed);
  if (seconds_since(last_write_) >= settings_.flush_interval_seconds || state_.unflushed_blocks() >= max_unwritten_blocks)
    write(store::RunStatus::running, elapsed);
  if (unpublished_ && seconds_since(last_publish_) >= pacing_.wait_seconds()) publish();
}

void Persistence::save_checkpoint(double elapsed) {
  const auto before = checkpointer_.bytes_written();
  checkpointer_.save(state_, elapsed);
  finished_since_checkpoint_ = 0;
  last_checkpoint_ = Clock::now();
  spdlog::debug("checkpoint written: {} of {} items; {} bytes written, checkpoint {} bytes, journal {} bytes",
                state_.items_done(), items_total_, checkpointer_.bytes_written() - before,
                checkpointer_.checkpoint_bytes(), checkpointer_.journal_bytes());
}

void Persistence::write(store::RunStatus state, double elapsed) {
  file_.write(state_.take_unflushed(), progress(state, elapsed));
  last_write_ = Clock::now();
  unpublished_ = true;
}

void Persistence::publish() {
  const auto start = Clock::now();
  file_.publish();
  pacing_.copied(seconds_since(start));
  last_publish_ = Clock::now();
  unpublished_ = false;
}

void Persistence::write_and_publish(store::RunStatus state, double elapsed) {
  write(state, elapsed);
  publish();
}

void Persistence::complete(double elapsed) {
  write(store::RunStatus::complete, elapsed);
  file_.complete();
  checkpointer_.remove_files();
}

}  // namespace pbrfit::runtime
