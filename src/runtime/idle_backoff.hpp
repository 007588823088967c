#pragma once
// How long a polling loop waits when nothing happened: 1 ms, doubling each idle round up to 4 ms, back
// to 1 ms as soon as something happens. Never shorter: on a loaded machine (and on virtual machines
// especially) threads that wake thousands of times a second take the processor from every other process,
// which then starts slowly. Private to the runtime.
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
  static constexpr std::chrono::microseconds shortest{1000}, longest{4000};
  std::chrono::microseconds pause_ = shortest;
};

}  // namespace pbrfit::runtime
