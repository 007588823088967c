#pragma once
// How many items rank 0 keeps out at each rank: every thread busy plus a reserve long enough to cover
// the polling delay (about 10 ms) at the rate the rank finishes items, so that neither long items (a few
// in reserve) nor tiny ones (hundreds) leave a thread waiting for the coordinator. Near the end of a
// stage only one item a thread, so the last items do not queue behind a busy rank while another is
// idle. Private to the runtime.
#include <chrono>
#include <cstddef>
#include <vector>

namespace pbrfit::runtime {

class DispatchDepth {
 public:
  using Clock = std::chrono::steady_clock;
  explicit DispatchDepth(std::vector<int> threads);

  void finished(int rank) { ++finished_[std::size_t(rank)]; }
  // Measures each rank's rate over windows of a tenth of a second (smoothed) and sets the reserves from it.
  void update(Clock::time_point now);
  std::size_t for_rank(int rank, std::size_t items_left) const;

 private:
  std::vector<int> threads_;
  std::vector<double> rate_;          // items per second, by rank
  std::vector<std::size_t> finished_;  // in the current window
  std::vector<std::size_t> reserve_;
  std::size_t total_depth_ = 0;
  Clock::time_point window_start_ = Clock::now();
};

}  // namespace pbrfit::runtime
