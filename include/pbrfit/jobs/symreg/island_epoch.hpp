#pragma once
// What one island's epoch of a symbolic-regression job carries (the island model of Brady et al., section
// 3.2, on the runtime): the island's state after the epoch (population and the non-dominated programs it
// has seen), what entered that front during the epoch (rows of the archive table), and the epoch's counts.
// The next epoch's input is the state plus the migrants from the island before it on the ring.
//
// Contract: decode(encode(x)) == x; decoding validates every program against the output's input count and
// throws RunError (naming what is wrong) for bytes that are not an island epoch.
#include <cstdint>
#include <limits>
#include <vector>

#include "pbrfit/core/bytes.hpp"
#include "pbrfit/gp/pareto_archive.hpp"
#include "pbrfit/gp/population.hpp"

namespace pbrfit::jobs::symreg {

struct IslandState {
  gp::Population population;
  std::vector<gp::ArchiveEntry> front;
  bool reached_target = false;  // the island has reached the job's target error (it then stops evolving)
};

struct IslandEpoch {
  IslandState state;
  std::vector<gp::Individual> emigrants;  // the island's best, for the next island on the ring
  std::vector<gp::ArchiveEntry> additions;
  std::uint64_t evaluations = 0;  // spent in this epoch
  double best_error = std::numeric_limits<double>::infinity();
};

// An epoch's input: the previous state (none in the first epoch), the migrants, and whether the output
// has been solved (every island then stops).
struct EpochInput {
  bool has_state = false;
  IslandState state;
  std::vector<gp::Individual> migrants;
  bool solved = false;
};

Bytes encode_epoch(const IslandEpoch& epoch);
IslandEpoch decode_epoch(std::span<const std::byte> bytes, std::size_t input_count);

// What rank 0 reads of an epoch for the result file and the summary, without decoding the population.
struct EpochRecord {
  std::uint64_t generation = 0;  // the island's generations completed
  std::vector<gp::ArchiveEntry> front;
  std::vector<gp::ArchiveEntry> additions;
  std::uint64_t evaluations = 0;
  double best_error = std::numeric_limits<double>::infinity();
};
EpochRecord decode_record(std::span<const std::byte> bytes, std::size_t input_count);

// Rank 0 builds the next epoch's inputs without decoding programs: an epoch's bytes start with the
// island's flag, its emigrants and its state, which the input reuses byte for byte (the worker validates).
struct EpochBytes {
  bool reached_target = false;
  Bytes emigrants;  // individuals_to_bytes
  Bytes state;      // the state as encode_input writes it
};
EpochBytes split_epoch(std::span<const std::byte> bytes);
// The flag alone (the first byte; false for bytes too short to hold it).
inline bool reached_target_of(std::span<const std::byte> bytes) { return !bytes.empty() && bytes[0] != std::byte{0}; }
// The input of an island's next epoch from its own epoch and its ring neighbour's.
Bytes next_input(const EpochBytes& own, const EpochBytes& neighbour, bool solved);
Bytes encode_input(const EpochInput& input);
EpochInput decode_input(std::span<const std::byte> bytes, std::size_t input_count);

}  // namespace pbrfit::jobs::symreg
