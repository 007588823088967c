#pragma once
// Rank 0's side of a run: hands out work items (up to two outstanding per rank, so no rank waits
// on the coordinator), collects results, streams them to the result file, writes checkpoints and logs
// progress. Stops early on a signal or a failure anywhere, always leaving a consistent checkpoint.
#include <chrono>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "local_worker.hpp"
#include "messages.hpp"
#include "pbrfit/runtime/job_runner.hpp"
#include "pbrfit/store/checkpoint_file.hpp"
#include "pbrfit/store/result_file.hpp"

namespace pbrfit::runtime {

enum class Outcome { complete, interrupted, failed };

class Coordinator {
 public:
  Coordinator(const MpiSession& mpi, const Workload& workload, const RunSettings& settings,
              store::Checkpoint resumed, store::ResultFile& file);
  Outcome run();

 private:
  using Clock = std::chrono::steady_clock;

  void run_stage(std::uint32_t stage);
  void finish(Outcome outcome);
  void dispatch(std::deque<std::uint64_t>& todo, std::uint32_t stage);
  bool poll();  // true when something arrived
  void handle(Message& message);
  void accept(WorkItemId id, Bytes result);
  void stop_all_workers();
  void maybe_checkpoint();
  void maybe_flush();
  void maybe_log_progress();
  void write_checkpoint();
  store::Progress progress(const std::string& state) const;
  double elapsed() const;
  std::size_t outstanding() const;

  const MpiSession& mpi_;
  const Workload& workload_;
  const RunSettings& settings_;
  store::ResultFile& file_;
  store::Checkpoint checkpoint_;  // results so far; written as is
  LocalWorker local_;
  std::vector<std::size_t> remote_outstanding_;  // by rank; [0] unused
  Bytes context_;
  std::uint64_t total_items_ = 0;
  std::uint64_t done_at_start_ = 0;
  double elapsed_before_ = 0.0;  // compute time of the runs this one resumes
  std::uint64_t done_since_checkpoint_ = 0;
  Clock::time_point started_ = Clock::now();
  Clock::time_point last_checkpoint_ = started_, last_flush_ = started_, last_progress_ = started_;
  std::optional<std::string> failure_;
  bool interrupted_ = false;
};

}  // namespace pbrfit::runtime
