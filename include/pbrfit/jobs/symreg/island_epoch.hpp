#pragma once
// What one island's epoch of a symbolic-regression job carries (the island model of Brady et al., section
// 3.2, on the runtime): the island's state after the epoch (population and the non-dominated programs it
// has seen), its best programs for the next island on the ring, what entered its front during the epoch
// (rows of the archive table), and the epoch's counts. The next epoch's input is the state plus the
// migrants from the island before it on the ring.
//
// Programs travel in gp's own compact encoding (gp/program_bytes.hpp), which needs the output's input
// count to be read back and validated; the types below hold them as those bytes (core/serial.hpp sends the
// rest), so rank 0 hands an island's population on to its next epoch without decoding it. The functions
// decode them where the input count is known and throw RunError for bytes that are not such programs.
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "pbrfit/core/bytes.hpp"
#include "pbrfit/gp/pareto.hpp"
#include "pbrfit/gp/population.hpp"

namespace pbrfit::jobs::symreg {

struct IslandState {
  gp::Population population;
  std::vector<gp::ArchiveEntry> front;
  bool reached_target = false;  // the island has reached the job's target error (it then stops evolving)
};

// An island's state with its programs encoded.
struct EncodedState {
  Bytes population;  // gp::population_to_bytes
  Bytes front;       // gp::archive_to_bytes
  bool reached_target = false;
  template <class Archive>
  void serialize(Archive& archive) {
    archive(population, front, reached_target);
  }
};

// The result of an island's epoch.
struct EpochResult {
  EncodedState state;
  std::uint64_t generation = 0;  // the island's generations completed
  Bytes emigrants;               // gp::individuals_to_bytes: the island's best, for the next island on the ring
  Bytes additions;               // gp::archive_to_bytes: what entered the front in this epoch
  std::uint64_t evaluations = 0;  // spent in this epoch
  double best_error = std::numeric_limits<double>::infinity();
  template <class Archive>
  void serialize(Archive& archive) {
    archive(state, generation, emigrants, additions, evaluations, best_error);
  }
};

// An epoch's input: the previous state (none in the first epoch), the migrants, and whether the output
// has been solved (every island then stops).
struct EpochInput {
  std::optional<EncodedState> state;
  Bytes migrants;  // gp::individuals_to_bytes
  bool solved = false;
  template <class Archive>
  void serialize(Archive& archive) {
    archive(state, migrants, solved);
  }
};

EncodedState encode_state(const IslandState& state);
IslandState decode_state(const EncodedState& state, std::size_t input_count);

// What rank 0 reads of an epoch for the result file and the summary: its programs, not its population.
struct EpochRecord {
  std::uint64_t generation = 0;
  std::vector<gp::ArchiveEntry> front;
  std::vector<gp::ArchiveEntry> additions;
  std::uint64_t evaluations = 0;
  double best_error = std::numeric_limits<double>::infinity();
};
EpochRecord epoch_record(const EpochResult& epoch, std::size_t input_count);

}  // namespace pbrfit::jobs::symreg
