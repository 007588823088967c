#pragma once
// Counter-based random streams. A stream is a pure function of its key, so results never depend on rank,
// thread, time or arrival order. The runtime keys every work item's streams by (job seed, stage, item,
// substream): two items, or two stages of one item (two epochs of an island), never share numbers.
// SplitMix64 over a hashed key; cheap to create.
#include <cstdint>

namespace pbrfit {

class RandomStream {
 public:
  // The stream of a work item: what ItemTask::random() hands to a job kind.
  RandomStream(std::uint64_t seed, std::uint32_t stage, std::uint64_t item, std::uint64_t substream);
  // A stream keyed by (seed, index, substream), for engines and tests that need one outside the runtime.
  RandomStream(std::uint64_t seed, std::uint64_t index, std::uint64_t substream = 0);

  std::uint64_t next_u64();
  // Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(next_u64() >> 11) * 0x1.0p-53; }
  // Uniform in [0, n) for n > 0, unbiased (rejection of the few values that would favour low residues).
  std::uint64_t below(std::uint64_t n);

  // An independent stream keyed by this stream's key and k: it does not depend on how many numbers
  // this stream has produced, so one stream per slot (individual, sample, restart) stays reproducible.
  RandomStream derive(std::uint64_t k) const;

 private:
  explicit RandomStream(std::uint64_t key) : key_(key), state_(key) {}
  std::uint64_t key_;
  std::uint64_t state_;
};

// A well-mixed 64-bit hash step (SplitMix64 finalizer).
std::uint64_t mix64(std::uint64_t x);

}  // namespace pbrfit
