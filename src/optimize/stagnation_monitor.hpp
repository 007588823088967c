#pragma once
// Counts consecutive generations in which the best value did not improve by more than
// max(absolute, relative |reference|), where the reference is the best value at the last improvement.
#include <cstddef>
#include <limits>

namespace pbrfit::optimize::detail {

class StagnationMonitor {
 public:
  StagnationMonitor(double relative, double absolute) : relative_(relative), absolute_(absolute) {}

  void observe(double best);
  std::size_t stale_generations() const { return stale_; }

 private:
  double relative_;
  double absolute_;
  double reference_ = std::numeric_limits<double>::infinity();
  std::size_t stale_ = 0;
};

}  // namespace pbrfit::optimize::detail
