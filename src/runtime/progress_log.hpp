#pragma once
// The progress line rank 0 logs every few seconds: percent done, items per second, ETA and the job
// kind's headline. Private to the runtime.
#include <chrono>
#include <cstdint>
#include <optional>

#include "pbrfit/runtime/workload.hpp"
#include "run_state.hpp"

namespace pbrfit::runtime {

class ProgressLog {
 public:
  ProgressLog(const Workload& workload, double interval_seconds, std::uint64_t done_at_start);
  void maybe_log(const RunState& state);

 private:
  using Clock = std::chrono::steady_clock;
  const Workload& workload_;
  const double interval_seconds_;
  const std::uint64_t items_total_, done_at_start_;
  const Clock::time_point started_ = Clock::now();
  Clock::time_point last_ = started_;
  std::optional<double> work_at_start_;  // Workload::work_done when the run began
};

}  // namespace pbrfit::runtime
