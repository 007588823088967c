#pragma once
// Continuing a job from its checkpoint: the checkpoint is read and checked against the workload in full
// (every stage, item, kept result, pending row and the summary) before anything is written, and the
// result file is rebuilt from the block journal. Private to the runtime.
#include <cstdint>
#include <string>

#include "pbrfit/runtime/workload.hpp"
#include "pbrfit/store/block_codec.hpp"
#include "pbrfit/store/checkpoint_file.hpp"
#include "pbrfit/store/result_file.hpp"

namespace pbrfit::runtime {

// Throws InputError naming the checkpoint for anything this workload could not have written.
void check_checkpoint(const std::string& path, const store::CheckpointState& state, const Workload& workload,
                      const store::BlockCodec& codec);

// Writes every block of the journal's first `length` bytes into the (fresh) result file, in batches.
// Throws InputError naming the journal when it is damaged or belongs to another job text.
void rebuild_result_file(store::ResultFile& file, const std::string& journal, const std::string& job_text,
                         const store::BlockCodec& codec, std::uint64_t length, const store::Progress& progress);

}  // namespace pbrfit::runtime
