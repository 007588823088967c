#pragma once
// The compute threads of one process. The main thread (the only one that calls MPI) assigns items and
// takes finished ones; the threads run Workload::compute. Every item carries its own stage context, so
// items of different stages never see each other's context.
//
// Invariant: an item counts as outstanding from assign() until its result (or failure) has been taken
// by take_finished(); so "nothing outstanding" means every result is in the caller's hands.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "pbrfit/runtime/workload.hpp"

namespace pbrfit::runtime {

struct FinishedItem {
  WorkItemId id;
  Bytes result;
  double seconds = 0.0;  // how long compute() took (for the log; never part of a result)
};

class ComputePool {
 public:
  ComputePool(const Workload& workload, std::uint64_t seed, int threads);
  ~ComputePool();  // stop()
  ComputePool(const ComputePool&) = delete;
  ComputePool& operator=(const ComputePool&) = delete;

  void assign(WorkItemId id, std::shared_ptr<const Bytes> context, Bytes input);
  std::size_t outstanding() const;
  // Items assigned and not started yet; results finished and not taken yet.
  std::size_t queued() const;
  std::size_t finished() const;
  int threads() const { return int(threads_.size()); }
  std::vector<FinishedItem> take_finished();
  // The first failure ("item N of stage S: what"); after one, queued items are dropped.
  std::optional<std::string> failure() const;
  // Returns when more than `held` results wait to be taken or an item failed, or after `timeout` (a caller
  // holding results back passes their number, so that it sleeps rather than spins); a timeout of zero
  // yields the processor once and returns.
  void wait(std::chrono::microseconds timeout, std::size_t held = 0);
  // Drops queued items and raises the cancel flag for running ones (which may finish or give up); new
  // items are refused from now on. Returns at once.
  void cancel();
  // Whether no item is running.
  bool idle() const;
  // cancel(), then joins the threads. Results that finished stay in take_finished().
  void stop();

 private:
  struct Task {
    WorkItemId id;
    std::shared_ptr<const Bytes> context;
    Bytes input;
  };
  void serve();
  void run(Task& task, std::unique_lock<std::mutex>& lock);

  const Workload& workload_;
  const std::uint64_t seed_;
  mutable std::mutex mutex_;
  std::condition_variable work_ready_, item_done_;
  std::deque<Task> queue_;
  std::vector<FinishedItem> finished_;
  std::optional<std::string> failure_;
  std::size_t running_ = 0;
  bool stopping_ = false;
  std::atomic<bool> cancelled_{false};
  std::vector<std::thread> threads_;
};

}  // namespace pbrfit::runtime
