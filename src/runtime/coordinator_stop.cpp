// How rank 0 ends a run: the checkpoint first, then a bounded wait for the other ranks, then the outcome.
#include <spdlog/spdlog.h>

#include <thread>

#include "coordinator.hpp"

namespace pbrfit::runtime {

namespace {

// A rank that has not even sent a heartbeat for this long is not waited for when stopping.
constexpr double presumed_gone_seconds = 3.0;

}  // namespace

// Before anything can delay the exit, what rank 0 holds is saved: a launcher that kills the ranks soon
// after a stop signal (mpirun: 2 s) then costs nothing.
void Coordinator::save_before_stopping() {
  if (state_.finished()) return;
  try {
    if (state_.has_news()) persistence_.save_checkpoint(elapsed());
    persistence_.write_and_publish(failure_ ? store::RunStatus::failed : store::RunStatus::interrupted, elapsed());
  } catch (const std::exception& e) {
    spdlog::error("cannot save the checkpoint: {}", e.what());
  }
}

void Coordinator::stop_everything() {
  save_before_stopping();
  pool_.cancel();
  for (int r = 1; r < mpi_.size(); ++r)
    if (r != lost_rank_) outbox_.send(r, Tag::stop);
  const auto grace = std::chrono::duration<double>(settings_.stop_grace_seconds);
  collect_until(Clock::now() + std::chrono::duration_cast<Clock::duration>(grace));
  if (!pool_.idle()) spdlog::warn("waiting for the work items in progress on rank 0 to finish");
  pool_.stop();
  for (auto& finished : pool_.take_finished()) accept(finished.id, std::move(finished.result), finished.seconds);
  for (int r = 1; r < mpi_.size(); ++r)
    if (!said_bye_[std::size_t(r)] && r != lost_rank_)
      spdlog::error("rank {} did not answer within {} s of the stop", r, settings_.stop_grace_seconds);
}

// Collects what the other ranks and the local threads still deliver, until every rank said bye and no
// local item runs, or the deadline.
void Coordinator::collect_until(Clock::time_point deadline) {
  while ((!all_answered() || !pool_.idle()) && Clock::now() < deadline) {
    outbox_.progress();
    bool busy = false;
    try {
      busy = poll();
    } catch (const std::exception& e) {
      if (!failure_) failure_ = e.what();
    }
    if (!busy) pool_.wait(std::chrono::milliseconds(1));
  }
}

bool Coordinator::all_answered() const {
  for (int r = 1; r < mpi_.size(); ++r)
    if (!said_bye_[std::size_t(r)] && r != lost_rank_ && peers_.silent_seconds(r) < presumed_gone_seconds) return false;
  return true;
}

void Coordinator::finish(Outcome outcome) {
  if (outcome == Outcome::complete) {
    persistence_.complete(elapsed());
    return;
  }
  if (state_.has_news()) persistence_.save_checkpoint(elapsed());
  persistence_.write_and_publish(outcome == Outcome::failed ? store::RunStatus::failed : store::RunStatus::interrupted, elapsed());
}

bool Coordinator::say_farewell(int code) {
  ByteWriter out;
  out.put<std::int32_t>(code);
  bool everyone = true;
  for (int r = 1; r < mpi_.size(); ++r) {
    if (said_bye_[std::size_t(r)]) outbox_.send(r, Tag::farewell, out.bytes());
    else everyone = false;
  }
  if (!outbox_.drain(std::chrono::milliseconds(2000))) everyone = false;
  return everyone;
}

}  // namespace pbrfit::runtime
