#include "stagnation_monitor.hpp"

#include <algorithm>
#include <cmath>

namespace pbrfit::optimize::detail {

void StagnationMonitor::observe(double best) {
  const bool first_finite = !std::isfinite(reference_) && std::isfinite(best);
  const double threshold = std::max(absolute_, relative_ * std::abs(reference_));
  if (first_finite || reference_ - best > threshold) {
    reference_ = best;
    stale_ = 0;
  } else {
    ++stale_;
  }
}

}  // namespace pbrfit::optimize::detail
