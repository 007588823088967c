#pragma once
// The compute thread of rank 0: takes items from a queue, leaves results for the coordinator thread.
#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "pbrfit/core/item_results.hpp"
#include "pbrfit/runtime/workload.hpp"

namespace pbrfit::runtime {

class LocalWorker {
 public:
  explicit LocalWorker(const Workload& workload);
  ~LocalWorker();

  // The context of the items assigned from now on; only while nothing is outstanding.
  void set_context(const Bytes* context) { context_ = context; }
  void assign(WorkItemId id);
  std::size_t outstanding() const;
  std::vector<std::pair<WorkItemId, Bytes>> take_results();
  std::optional<std::string> failure() const;
  // Drops queued items, waits for the one in progress (its result stays in take_results()).
  void stop();

 private:
  void serve();

  const Workload& workload_;
  const Bytes* context_ = nullptr;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<WorkItemId> queue_;
  std::vector<std::pair<WorkItemId, Bytes>> results_;
  std::optional<std::string> failure_;
  std::size_t in_progress_ = 0;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace pbrfit::runtime
