#include "pbrfit/core/random_stream.hpp"

namespace pbrfit {

std::uint64_t mix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

namespace {

// Distinct key domains, so a (seed, index) stream never equals a work item's stream.
constexpr std::uint64_t item_domain = 0x6974656d5f6b6579ULL;
constexpr std::uint64_t index_domain = 0x696e6465785f6b79ULL;

}  // namespace

RandomStream::RandomStream(std::uint64_t seed, std::uint32_t stage, std::uint64_t item, std::uint64_t substream)
    : RandomStream(mix64(mix64(mix64(mix64(seed ^ item_domain) ^ stage) ^ item) ^ substream)) {}

RandomStream::RandomStream(std::uint64_t seed, std::uint64_t index, std::uint64_t substream)
    : RandomStream(mix64(mix64(mix64(seed ^ index_domain) ^ index) ^ substream)) {}

RandomStream RandomStream::derive(std::uint64_t k) const { return RandomStream(mix64(mix64(key_) ^ k)); }

std::uint64_t RandomStream::next_u64() {
  state_ += 0x9e3779b97f4a7c15ULL;
  std::uint64_t z = state_;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

std::uint64_t RandomStream::below(std::uint64_t n) {
  // Values below 2^64 mod n would make the low residues more likely; they are drawn again.
  const std::uint64_t threshold = (0 - n) % n;
  for (;;) {
    const std::uint64_t r = next_u64();
    if (r >= threshold) return r % n;
  }
}

}  // namespace pbrfit
