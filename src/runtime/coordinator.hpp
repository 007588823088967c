#pragma once
// Rank 0's side of a run. Per stage it builds the stage context from complete earlier stages, relays it
// down the tree, and hands out items with their inputs to its own compute threads and to the other ranks
// (enough per thread that no thread waits for the coordinator). It folds results into the run state and
// lets Persistence write them; a resumed run's result file says "running" from its start. It watches every
// rank: one silent for rank_timeout_seconds is lost.
//
// Stopping (a signal, a failure or a lost rank, anywhere): the checkpoint is saved first, then work is
// cancelled everywhere and in-flight results are collected for at most stop_grace_seconds, so a dead or
// hung rank can delay the exit but never cost the checkpoint.
#include <chrono>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "compute_pool.hpp"
#include "coordinator_load.hpp"
#include "dispatch_depth.hpp"
#include "idle_backoff.hpp"
#include "messages.hpp"
#include "peer_watch.hpp"
#include "persistence.hpp"
#include "pbrfit/runtime/job_runner.hpp"
#include "progress_log.hpp"
#include "run_state.hpp"

namespace pbrfit::runtime {

enum class Outcome { complete, interrupted, failed, lost_rank };

class Coordinator {
 public:
  Coordinator(const MpiSession& mpi, const Workload& workload, const RunSettings& settings, RunState& state,
              Persistence& persistence, std::vector<int> threads, double elapsed_before);
  Outcome run();
  // Tells every rank that said bye its exit code. False if some rank never answered (dead or hung).
  bool say_farewell(int code);

 private:
  using Clock = std::chrono::steady_clock;

  void begin_stage();
  void run_stage();
  bool stopping() const { return failure_ || interrupted_ || lost_rank_; }
  void check_stop_signal();
  void watch_peers();
  void dispatch();
  bool poll();  // true when something arrived
  void handle(Message& message);
  void accept(WorkItemId id, Bytes result, double seconds);
  void save_before_stopping();
  void stop_everything();
  void collect_until(Clock::time_point deadline);
  bool all_answered() const;
  void finish(Outcome outcome);
  double elapsed() const;

  const MpiSession& mpi_;
  const Workload& workload_;
  const RunSettings& settings_;
  RunState& state_;
  Persistence& persistence_;
  const std::vector<int> threads_;  // compute threads by rank
  DispatchDepth depth_;
  Outbox outbox_;
  IdleBackoff backoff_;
  PeerWatch peers_;
  HeartbeatClock heartbeat_;
  ProgressLog progress_;
  ComputePool pool_;
  std::shared_ptr<const Bytes> context_;
  std::deque<std::uint64_t> todo_;
  std::vector<std::size_t> sent_;  // items out at each remote rank; [0] unused
  std::vector<bool> said_bye_;
  double elapsed_before_ = 0.0;
  Clock::time_point started_ = Clock::now();
  std::optional<std::string> failure_;
  std::optional<int> lost_rank_;
  bool interrupted_ = false;
  CoordinatorLoad load_;
};

}  // namespace pbrfit::runtime
