#pragma once
// How long a polling loop waits when nothing happened. Two regimes:
//  - Nothing runs on this rank's compute threads (a worker that sent its last results, rank 0 waiting for
//    the last results of a stage): the rank is waiting for a message that usually comes within a
//    millisecond (the next stage, more work, the last results), and its core has nothing else to do. It
//    polls without sleeping (yielding the processor each round) for up to `spin` after the last thing
//    that happened, so a stage boundary costs message latencies, not sleeps.
//  - Otherwise, or once the spin is over: 250 us, doubling each idle round up to 1 ms, back to the start
//    as soon as something happens. A message from another rank is noticed within about 1 ms, and an idle
//    rank wakes at most 1000 times a second (more would take the processor from other processes on loaded
//    and virtual machines). Waits end early when a local compute thread finishes.
// So a rank spins for at most `spin` per burst of activity: a job's stage boundaries, not its items.
// Private to the runtime.
#include <algorithm>
#include <chrono>

namespace pbrfit::runtime {

class IdleBackoff {
 public:
  using Clock = std::chrono::steady_clock;

  // A pause of zero means: poll again at once (ComputePool::wait yields the processor for it).
  std::chrono::microseconds next(bool busy, bool nothing_running, Clock::time_point now = Clock::now()) {
    if (busy) {
      last_busy_ = now;
      pause_ = shortest;
      return nothing_running ? std::chrono::microseconds(0) : pause_;
    }
    if (nothing_running && now - last_busy_ < spin) return std::chrono::microseconds(0);
    const auto pause = pause_;
    pause_ = std::min(pause_ * 2, longest);
    return pause;
  }

 private:
  static constexpr std::chrono::microseconds shortest{250}, longest{1000}, spin{1000};
  std::chrono::microseconds pause_ = shortest;
  Clock::time_point last_busy_ = Clock::now();
};

}  // namespace pbrfit::runtime
