#pragma once
// How long rank 0 waits between publications of the result file: at least the flush interval, and long
// enough that copying takes at most 5 % of the time. A copy's cost is judged by the median of the last
// five copies, copies not yet made counting as free, so one copy stalled by a busy disk (the first one
// included: a cold disk makes it the slowest) does not hold back the next publication for twenty times
// its length (readers such as `pbrfit status` would see no progress meanwhile); three slow copies in
// five are believed. Private to the runtime.
#include <algorithm>
#include <array>
#include <cstddef>

namespace pbrfit::runtime {

class PublishPacing {
 public:
  explicit PublishPacing(double flush_interval_seconds)
      : flush_interval_seconds_(flush_interval_seconds), wait_seconds_(flush_interval_seconds) {}

  void copied(double seconds) {
    recent_[next_ % recent_.size()] = seconds;
    ++next_;
    wait_seconds_ = std::max(flush_interval_seconds_, typical_cost() / max_share);
  }

  double wait_seconds() const { return wait_seconds_; }

 private:
  static constexpr double max_share = 0.05;

  double typical_cost() const {
    std::array<double, 5> sorted = recent_;
    std::sort(sorted.begin(), sorted.end());
    return sorted[sorted.size() / 2];
  }

  double flush_interval_seconds_;
  double wait_seconds_;  // a function of the above and recent_, kept because rank 0's loop asks often
  std::array<double, 5> recent_{};  // copy costs in seconds; zero until that many copies were made
  std::size_t next_ = 0;
};

}  // namespace pbrfit::runtime
