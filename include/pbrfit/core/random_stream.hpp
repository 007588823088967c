#pragma once
// Counter-based random streams: stream (seed, item, substream) is a pure function of its key, so
// results never depend on rank, time or arrival order. SplitMix64 over a hashed key; cheap to create.
#include <cstdint>

namespace pbrfit {

class RandomStream {
 public:
  RandomStream(std::uint64_t seed, std::uint64_t item, std::uint64_t substream = 0);

  std::uint64_t next_u64();
  // Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(next_u64() >> 11) * 0x1.0p-53; }

 private:
  std::uint64_t state_;
};

// A well-mixed 64-bit hash step (SplitMix64 finalizer).
std::uint64_t mix64(std::uint64_t x);

}  // namespace pbrfit
