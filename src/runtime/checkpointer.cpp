#include "checkpointer.hpp"

#include <cstdio>

namespace pbrfit::runtime {

Checkpointer Checkpointer::start(const std::string& output, const std::string& job_text, RunState& state) {
  // The old checkpoint goes first: a kill before the new snapshot leaves no checkpoint (a fresh start),
  // never an old checkpoint beside a new journal.
  std::remove(store::checkpoint_path_for(output).c_str());
  Checkpointer c(output, job_text, store::BlockJournal::create(store::journal_path_for(output), job_text));
  c.save(state, 0.0);
  return c;
}

Checkpointer Checkpointer::resume(const std::string& output, const std::string& job_text, std::uint64_t journal_length,
                                  std::uint64_t checkpoint_length) {
  Checkpointer c(output, job_text, store::BlockJournal::reopen(store::journal_path_for(output), journal_length));
  c.checkpoint_.continue_after(checkpoint_length);
  return c;
}

void Checkpointer::save(RunState& state, double elapsed) {
  const auto& blocks = state.unjournaled();
  if (blocks.count() > 0) {
    journal_.append(blocks.count(), blocks.bytes());
    state.journaled();
  }
  if (state.needs_snapshot()) checkpoint_.write_snapshot(state.snapshot(job_text_, elapsed, journal_.length()));
  else checkpoint_.append(state.progress(elapsed, journal_.length()));
  state.saved();
}

void Checkpointer::remove_files() {
  std::remove(store::checkpoint_path_for(output_).c_str());
  std::remove(store::journal_path_for(output_).c_str());
}

}  // namespace pbrfit::runtime
