#include "dispatch_depth.hpp"

#include <algorithm>
#include <cmath>

namespace pbrfit::runtime {

namespace {

constexpr double covered_delay = 0.010;  // seconds
constexpr double window_seconds = 0.1;
constexpr std::size_t max_reserve = 1024;

}  // namespace

DispatchDepth::DispatchDepth(std::vector<int> threads)
    : threads_(std::move(threads)), rate_(threads_.size(), 0.0), finished_(threads_.size(), 0) {
  for (int t : threads_) reserve_.push_back(std::size_t(t));
  for (std::size_t r = 0; r < threads_.size(); ++r) total_depth_ += std::size_t(threads_[r]) + reserve_[r];
}

void DispatchDepth::update(Clock::time_point now) {
  const double seconds = std::chrono::duration<double>(now - window_start_).count();
  if (seconds < window_seconds) return;
  total_depth_ = 0;
  for (std::size_t r = 0; r < rate_.size(); ++r) {
    rate_[r] = 0.5 * rate_[r] + 0.5 * double(finished_[r]) / seconds;
    finished_[r] = 0;
    const auto threads = std::size_t(threads_[r]);
    reserve_[r] = std::clamp(std::size_t(std::ceil(rate_[r] * covered_delay)), threads, max_reserve);
    total_depth_ += threads + reserve_[r];
  }
  window_start_ = now;
}

std::size_t DispatchDepth::for_rank(int rank, std::size_t items_left) const {
  const auto r = std::size_t(rank);
  const auto threads = std::size_t(threads_[r]);
  return items_left <= total_depth_ ? threads : threads + reserve_[r];
}

}  // namespace pbrfit::runtime
