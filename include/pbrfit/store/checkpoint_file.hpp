#pragma once
// Checkpoints: everything a job needs to continue, i.e. the job text it belongs to, the stage it is in,
// the elapsed time so far and the result of every finished work item. Written atomically (temporary
// file, fsync, rename, fsync of the directory): a kill at any instant leaves the old or the new file.
//
// Format (little endian): "PBRFITCK", u32 format version, string job text, u32 stage, f64 elapsed
// seconds, u64 record count, records (u32 stage, u64 item, bytes result), u64 FNV-1a of all before.
#include <cstdint>
#include <string>

#include "pbrfit/core/item_results.hpp"

namespace pbrfit::store {

struct Checkpoint {
  std::string job_text;
  std::uint32_t stage = 0;
  double elapsed_seconds = 0.0;
  ItemResults results;
};

void write_checkpoint(const std::string& path, const Checkpoint& checkpoint);

// Throws InputError naming the file (and the byte offset where it went wrong) for any malformed file.
Checkpoint read_checkpoint(const std::string& path);

// The checkpoint that belongs to a result file.
std::string checkpoint_path_for(const std::string& result_path);

}  // namespace pbrfit::store
