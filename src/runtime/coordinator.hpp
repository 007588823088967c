#pragma once
// Rank 0's side of a run. Per stage it builds the stage context from complete earlier stages, relays it
// down the tree, and hands out items with their inputs to its own compute threads and to the other ranks
// (a few per thread, so no thread waits for the coordinator). It collects results into the run state,
// streams them to the result file, checkpoints and logs progress. On a signal or a failure anywhere it
// stops handing out work, collects what is in flight for a bounded time, and always leaves a checkpoint.
#include <chrono>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "checkpointer.hpp"
#include "compute_pool.hpp"
#include "dispatch_depth.hpp"
#include "idle_backoff.hpp"
#include "messages.hpp"
#include "pbrfit/runtime/job_runner.hpp"
#include "pbrfit/store/result_file.hpp"
#include "run_state.hpp"

namespace pbrfit::runtime {

enum class Outcome { complete, interrupted, failed };

class Coordinator {
 public:
  Coordinator(const MpiSession& mpi, const Workload& workload, const RunSettings& settings, RunState& state,
              Checkpointer& checkpointer, store::ResultFile& file, std::vector<int> threads, double elapsed_before);
  Outcome run();
  // Tells every rank that said bye its exit code (the other ranks are gone or hung).
  void say_farewell(int code);

 private:
  using Clock = std::chrono::steady_clock;

  void begin_stage();
  void run_stage();
  bool stopping() const { return failure_ || interrupted_; }
  void check_stop_signal();
  void dispatch();
  bool poll();  // true when something arrived
  void handle(Message& message);
  void accept(WorkItemId id, Bytes result);
  void stop_workers();
  void finish(Outcome outcome);
  void save_checkpoint();
  void maybe_checkpoint();
  void maybe_flush();
  void flush(const std::string& state);
  void maybe_log_progress();
  store::Progress progress(const std::string& state) const;
  double elapsed() const;

  const MpiSession& mpi_;
  const Workload& workload_;
  const RunSettings& settings_;
  RunState& state_;
  Checkpointer& checkpointer_;
  store::ResultFile& file_;
  const std::vector<int> threads_;  // compute threads by rank
  DispatchDepth depth_;
  Outbox outbox_;
  IdleBackoff backoff_;
  ComputePool pool_;
  std::shared_ptr<const Bytes> context_;
  std::deque<std::uint64_t> todo_;
  std::vector<std::size_t> sent_;   // items out at each remote rank; [0] unused
  std::vector<bool> said_bye_;
  std::uint64_t items_total_ = 0, done_at_start_ = 0, done_since_checkpoint_ = 0;
  double elapsed_before_ = 0.0;
  Clock::time_point started_ = Clock::now();
  Clock::time_point last_checkpoint_ = started_, last_flush_ = started_, last_progress_ = started_;
  std::optional<std::string> failure_;
  bool interrupted_ = false;
};

}  // namespace pbrfit::runtime
