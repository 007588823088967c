#include "local_worker.hpp"

namespace pbrfit::runtime {

LocalWorker::LocalWorker(const Workload& workload) : workload_(workload), thread_([this] { serve(); }) {}

LocalWorker::~LocalWorker() { stop(); }

void LocalWorker::assign(WorkItemId id) {
  {
    std::lock_guard lock(mutex_);
    queue_.push_back(id);
  }
  wake_.notify_one();
}

std::size_t LocalWorker::outstanding() const {
  std::lock_guard lock(mutex_);
  return queue_.size() + in_progress_;
}

std::vector<std::pair<WorkItemId, Bytes>> LocalWorker::take_results() {
  std::lock_guard lock(mutex_);
  return std::exchange(results_, {});
}

std::optional<std::string> LocalWorker::failure() const {
  std::lock_guard lock(mutex_);
  return failure_;
}

void LocalWorker::stop() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    queue_.clear();
  }
  wake_.notify_one();
  if (thread_.joinable()) thread_.join();
}

void LocalWorker::serve() {
  std::unique_lock lock(mutex_);
  for (;;) {
    wake_.wait(lock, [this] { return stopping_ || (!queue_.empty() && !failure_); });
    if (stopping_) return;
    const WorkItemId id = queue_.front();
    queue_.pop_front();
    ++in_progress_;
    const Bytes* context = context_;
    lock.unlock();
    std::optional<Bytes> result;
    std::optional<std::string> error;
    try {
      result = workload_.compute(id.stage, id.item, *context);
    } catch (const std::exception& e) {
      error = "item " + std::to_string(id.item) + ": " + e.what();
    }
    lock.lock();
    --in_progress_;
    if (result) results_.emplace_back(id, std::move(*result));
    if (error) {
      failure_ = std::move(error);
      queue_.clear();
    }
  }
}

}  // namespace pbrfit::runtime
