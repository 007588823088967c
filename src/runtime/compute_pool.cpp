#include "compute_pool.hpp"

namespace pbrfit::runtime {

ComputePool::ComputePool(const Workload& workload, std::uint64_t seed, int threads)
    : workload_(workload), seed_(seed) {
  for (int t = 0; t < std::max(threads, 1); ++t) threads_.emplace_back([this] { serve(); });
}

ComputePool::~ComputePool() { stop(); }

void ComputePool::assign(WorkItemId id, std::shared_ptr<const Bytes> context, Bytes input) {
  {
    std::lock_guard lock(mutex_);
    if (stopping_) return;
    queue_.push_back({id, std::move(context), std::move(input)});
  }
  work_ready_.notify_one();
}

std::size_t ComputePool::outstanding() const {
  std::lock_guard lock(mutex_);
  return queue_.size() + running_ + finished_.size();
}

std::size_t ComputePool::queued() const {
  std::lock_guard lock(mutex_);
  return queue_.size();
}

std::size_t ComputePool::finished() const {
  std::lock_guard lock(mutex_);
  return finished_.size();
}

std::vector<FinishedItem> ComputePool::take_finished() {
  std::lock_guard lock(mutex_);
  return std::exchange(finished_, {});
}

std::optional<std::string> ComputePool::failure() const {
  std::lock_guard lock(mutex_);
  return failure_;
}

void ComputePool::wait(std::chrono::microseconds timeout, std::size_t held) {
  if (timeout.count() <= 0) {
    std::this_thread::yield();
    return;
  }
  std::unique_lock lock(mutex_);
  item_done_.wait_for(lock, timeout, [&] { return finished_.size() > held || failure_; });
}

void ComputePool::cancel() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    queue_.clear();
  }
  cancelled_ = true;
  work_ready_.notify_all();
}

bool ComputePool::idle() const {
  std::lock_guard lock(mutex_);
  return running_ == 0;
}

void ComputePool::stop() {
  cancel();
  for (auto& t : threads_)
    if (t.joinable()) t.join();
}

void ComputePool::serve() {
  std::unique_lock lock(mutex_);
  for (;;) {
    work_ready_.wait(lock, [this] { return stopping_ || (!queue_.empty() && !failure_); });
    if (stopping_) return;
    Task task = std::move(queue_.front());
    queue_.pop_front();
    run(task, lock);
  }
}

void ComputePool::run(Task& task, std::unique_lock<std::mutex>& lock) {
  ++running_;
  lock.unlock();
  std::optional<Bytes> result;
  std::string error;
  const auto started = std::chrono::steady_clock::now();
  try {
    result = workload_.compute(ItemTask{task.id, *task.context, task.input, seed_, &cancelled_});
  } catch (const Cancelled&) {
    // gave up because the job stops: neither a result nor a failure
  } catch (const std::exception& e) {
    error = "item " + std::to_string(task.id.item) + " of stage " + std::to_string(task.id.stage) + ": " + e.what();
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const WorkItemId id = task.id;
  task = Task{};  // release the context before reporting
  lock.lock();
  --running_;
  if (result) finished_.push_back({id, std::move(*result), seconds});
  if (!error.empty() && !failure_ && !cancelled_) {
    failure_ = std::move(error);
    queue_.clear();
  }
  item_done_.notify_all();
}

}  // namespace pbrfit::runtime
