#pragma once
// What coordinating costs rank 0 and what items cost, for the verbose log and the cluster model
// (docs/BENCHMARKS.md, "Scale past one machine"; tests/benchmarks/cluster_model.py reads these lines):
//   per stage: "stage S: N items in W s; computing 7.1 ms an item on average, longest 9.8 ms", ending
//              "(of the stage's M)" when this run did fewer than all M (stopped, or resumed within it)
//   per run:   "coordinator: N items (R from other ranks; W work messages of B bytes and I items on average,
//               M result messages of B' bytes and I' items), main thread T s of processor time, U us per item"
// An item's cost is how long its compute() took, reported with its result (a clock read costs tens of
// nanoseconds; on a core of its own, as mpirun places ranks, that is the processor time it took); the
// main thread's processor time (thread_cpu_seconds) is everything else rank 0 does: MPI, dispatching,
// folding, files. Measured, never used to decide anything, so no result depends on it. Private to the
// runtime.
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include <time.h>

namespace pbrfit::runtime {

// The processor time the calling thread has used, in seconds: what coordinating cost the main thread,
// however many other processes share its core. A system call, not a vDSO read: once a run.
inline double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

class CoordinatorLoad {
 public:
  using Clock = std::chrono::steady_clock;

  void sent_work(std::size_t bytes, std::size_t items) {
    ++work_messages_;
    work_bytes_ += bytes;
    items_sent_ += items;
  }
  void received_results(std::size_t bytes, std::size_t items) {
    ++result_messages_;
    result_bytes_ += bytes;
    items_received_ += items;
  }
  void begin_stage(std::uint32_t stage) {
    stage_ = stage;
    stage_items_ = 0;
    stage_seconds_ = stage_longest_ = 0.0;
    stage_started_ = Clock::now();
  }
  void item_done(double seconds) {
    ++items_;
    ++stage_items_;
    stage_seconds_ += seconds;
    stage_longest_ = std::max(stage_longest_, seconds);
  }

  // `stage_items`: how many items the stage has; named when fewer were done (a stopped or resumed run).
  std::string stage_summary(std::uint64_t stage_items) const {
    const double wall = std::chrono::duration<double>(Clock::now() - stage_started_).count();
    char text[240];
    std::snprintf(text, sizeof text, "stage %u: %llu items in %.4f s; computing %.4g ms an item on average, longest %.4g ms",
                  stage_ + 1, static_cast<unsigned long long>(stage_items_), wall,
                  stage_items_ > 0 ? 1e3 * stage_seconds_ / double(stage_items_) : 0.0, 1e3 * stage_longest_);
    std::string line = text;
    if (stage_items_ < stage_items) line += " (of the stage's " + std::to_string(stage_items) + ")";
    return line;
  }

  std::string run_summary() const {
    const double cpu = thread_cpu_seconds() - cpu_started_;
    char text[400];
    std::snprintf(text, sizeof text,
                  "coordinator: %llu items (%llu from other ranks; %llu work messages of %.0f bytes and %.1f items "
                  "on average, %llu result messages of %.0f bytes and %.1f items), main thread %.3f s of processor "
                  "time, %.2f us per item",
                  static_cast<unsigned long long>(items_), static_cast<unsigned long long>(items_received_),
                  static_cast<unsigned long long>(work_messages_), mean(work_bytes_, work_messages_),
                  mean(items_sent_, work_messages_), static_cast<unsigned long long>(result_messages_),
                  mean(result_bytes_, result_messages_), mean(items_received_, result_messages_), cpu,
                  items_ > 0 ? 1e6 * cpu / double(items_) : 0.0);
    return text;
  }

 private:
  static double mean(std::uint64_t total, std::uint64_t count) { return count > 0 ? double(total) / double(count) : 0.0; }

  double cpu_started_ = thread_cpu_seconds();
  std::uint64_t items_ = 0, work_messages_ = 0, result_messages_ = 0, work_bytes_ = 0, result_bytes_ = 0;
  std::uint64_t items_sent_ = 0, items_received_ = 0;
  std::uint32_t stage_ = 0;
  std::uint64_t stage_items_ = 0;
  double stage_seconds_ = 0.0, stage_longest_ = 0.0;
  Clock::time_point stage_started_ = Clock::now();
};

}  // namespace pbrfit::runtime
