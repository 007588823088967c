#pragma once
// Makes rank 0's state durable beside the result file: first the blocks waiting for the block journal,
// then a checkpoint record that refers to the journal's new length. A kill between the two leaves the
// old checkpoint, which refers to a shorter journal: nothing it relies on is ever missing. Private to
// the runtime.
#include <cstdint>
#include <string>

#include "pbrfit/store/block_journal.hpp"
#include "pbrfit/store/checkpoint_file.hpp"
#include "run_state.hpp"

namespace pbrfit::runtime {

class Checkpointer {
 public:
  // A job from its beginning: an empty journal and a snapshot of the starting state.
  static Checkpointer start(const std::string& output, const std::string& job_text, RunState& state);
  // A job continued from its checkpoint: both files go on after what the checkpoint relies on.
  static Checkpointer resume(const std::string& output, const std::string& job_text, std::uint64_t journal_length,
                             std::uint64_t checkpoint_length);

  // Throws RunError; what was not saved stays in `state` for the next attempt.
  void save(RunState& state, double elapsed);
  // After the result file is complete and durable.
  void remove_files();

  std::uint64_t bytes_written() const { return journal_.bytes_written() + checkpoint_.bytes_written(); }
  std::uint64_t checkpoint_bytes() const { return checkpoint_.length(); }
  std::uint64_t journal_bytes() const { return journal_.length(); }

 private:
  Checkpointer(std::string output, std::string job_text, store::BlockJournal journal)
      : output_(std::move(output)),
        job_text_(std::move(job_text)),
        journal_(std::move(journal)),
        checkpoint_(store::checkpoint_path_for(output_)) {}
  std::string output_;
  std::string job_text_;
  store::BlockJournal journal_;
  store::CheckpointFile checkpoint_;
};

}  // namespace pbrfit::runtime
