#pragma once
// When each peer was last heard from. Every rank's main thread sends something (results, or a heartbeat)
// at least once a second whatever its compute threads do, so a peer silent for much longer has died or
// hangs. Private to the runtime.
#include <chrono>
#include <vector>

namespace pbrfit::runtime {

class PeerWatch {
 public:
  using Clock = std::chrono::steady_clock;
  explicit PeerWatch(int ranks) : last_heard_(std::size_t(ranks), Clock::now()) {}

  void heard(int rank) { last_heard_[std::size_t(rank)] = Clock::now(); }
  double silent_seconds(int rank) const {
    return std::chrono::duration<double>(Clock::now() - last_heard_[std::size_t(rank)]).count();
  }

 private:
  std::vector<Clock::time_point> last_heard_;
};

// Sends a heartbeat when nothing else was sent for a second.
class HeartbeatClock {
 public:
  using Clock = std::chrono::steady_clock;
  void sent() { last_sent_ = Clock::now(); }
  bool due() const { return Clock::now() - last_sent_ >= std::chrono::seconds(1); }

 private:
  Clock::time_point last_sent_ = Clock::now();
};

}  // namespace pbrfit::runtime
