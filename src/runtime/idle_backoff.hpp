#pragma once
// How long a polling loop waits when nothing happened: 250 us, doubling each idle round up to 1 ms, back
// to 250 us as soon as something happens. The bound is a trade: a message from another rank is noticed
// within about 1 ms, which a job of many short stages (island epochs) pays at every stage boundary on
// both sides, while an idle rank wakes at most 1000 times a second (more would take the processor from
// other processes on loaded and virtual machines). Waits end early when a local compute thread finishes.
// Private to the runtime.
#include <algorithm>
#include <chrono>

namespace pbrfit::runtime {

class IdleBackoff {
 public:
  std::chrono::microseconds next(bool busy) {
    pause_ = busy ? shortest : std::min(pause_ * 2, longest);
    return pause_;
  }

 private:
  static constexpr std::chrono::microseconds shortest{250}, longest{1000};
  std::chrono::microseconds pause_ = shortest;
};

}  // namespace pbrfit::runtime
