#pragma once
// What a run finds at its output before it starts: a checkpoint to resume or discard, and a result
// file that may be complete, damaged, or another job's. The policy: never resume, overwrite or discard
// the work of a different job text without --force; resume only with --resume. Private to the runtime.
#include <optional>

#include "pbrfit/runtime/job_runner.hpp"
#include "pbrfit/store/checkpoint_file.hpp"

namespace pbrfit::runtime {

struct ExistingOutput {
  std::optional<store::CheckpointReading> checkpoint;  // the checkpoint to resume from
  bool complete = false;   // --resume of this job's complete result with no checkpoint: nothing to do
  bool discards_checkpoint = false;  // starting over: the existing checkpoint will be replaced
};

// Throws InputError naming the file for a checkpoint or result that may not be used or overwritten.
ExistingOutput inspect_existing_output(const RunSettings& settings);

}  // namespace pbrfit::runtime
