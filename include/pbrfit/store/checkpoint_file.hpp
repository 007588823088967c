#pragma once
// The checkpoint: what a job needs to continue, apart from the blocks already in the block journal.
// It is a record log (record_log.hpp): a snapshot of the whole state, followed by one progress record
// per checkpoint since, each holding only what is new. A checkpoint after the stage has changed writes
// a new snapshot instead (atomically replacing the file), which leaves out results no later stage
// reads: the file stays as small as the job's live state.
//
// Invariants: every stage before `stage` is complete; `done` lists finished items of `stage` only;
// the blocks of every finished item are in the first `journal_length` bytes of the block journal,
// except rows of growing tables, which wait in `appends` until the stage ends.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "pbrfit/core/item_results.hpp"
#include "pbrfit/store/record_log.hpp"

namespace pbrfit::store {

struct CheckpointState {
  std::string job_text;
  std::uint32_t stage = 0;
  double elapsed_seconds = 0.0;
  Bytes summary;                               // the job kind's running summary
  std::vector<std::uint64_t> rows;             // rows appended so far, per growing table
  std::uint64_t journal_length = 0;            // bytes of the block journal this state relies on
  ItemResults retained;                        // results that stage `stage` or later still reads
  std::vector<std::uint64_t> done;             // finished items of `stage`, in the order recorded
  std::map<std::uint64_t, Bytes> appends;      // encoded growing-table blocks of finished items
};

// What one checkpoint adds to the state.
struct FinishedItem {
  std::uint64_t item = 0;
  std::optional<Bytes> retained;
  Bytes appends;
};
struct CheckpointProgress {
  double elapsed_seconds = 0.0;
  Bytes summary;
  std::vector<std::uint64_t> rows;
  std::uint64_t journal_length = 0;
  std::vector<FinishedItem> finished;
};

class CheckpointFile {
 public:
  explicit CheckpointFile(std::string path) : path_(std::move(path)) {}

  // Replaces the file with a snapshot of `state`.
  void write_snapshot(const CheckpointState& state);
  // Continues the file read by read_checkpoint, after its last good record.
  void continue_after(std::uint64_t valid_length);
  void append(const CheckpointProgress& progress);

  const std::string& path() const { return path_; }
  std::uint64_t bytes_written() const { return written_; }  // by this object, for benchmarks
  std::uint64_t length() const { return log_ ? log_->length() : 0; }

 private:
  std::string path_;
  std::optional<RecordLog> log_;
  std::uint64_t written_ = 0;
};

struct CheckpointReading {
  CheckpointState state;
  std::uint64_t valid_length = 0;
  bool torn_tail = false;  // the last checkpoint was cut short; the one before it is used
};

// Throws InputError naming the file for anything that is not an intact checkpoint.
CheckpointReading read_checkpoint(const std::string& path);

// The files that belong to a result file: its checkpoint and its block journal.
std::string checkpoint_path_for(const std::string& result_path);
std::string journal_path_for(const std::string& result_path);

}  // namespace pbrfit::store
