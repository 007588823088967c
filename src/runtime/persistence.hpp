#pragma once
// When rank 0's state reaches the disk. Finished blocks go into the result file's working copy about
// once a second (sooner when many wait), which is published to readers as PublishPacing allows (copying
// grows with the file); blocks go
// to the block journal, and what is new to the checkpoint, at the job's checkpoint interval (sooner when
// many wait). Private to the runtime.
#include <chrono>
#include <cstdint>
#include <string>

#include "checkpointer.hpp"
#include "pbrfit/runtime/job_runner.hpp"
#include "pbrfit/store/result_file.hpp"
#include "publish_pacing.hpp"
#include "run_state.hpp"

namespace pbrfit::runtime {

class Persistence {
 public:
  Persistence(const RunSettings& settings, const Workload& workload, RunState& state, Checkpointer& checkpointer,
              store::ResultFile& file);

  void finished_one() { ++finished_since_checkpoint_; }
  // Writes, publishes and checkpoints whatever is due. Throws RunError on I/O failure.
  void tick(double elapsed);
  void save_checkpoint(double elapsed);
  // Writes the result file with the given state and publishes it.
  void write_and_publish(store::RunStatus state, double elapsed);
  // The job is complete: last write, the result file renamed into place, checkpoint and journal removed.
  void complete(double elapsed);
  store::Progress progress(store::RunStatus state, double elapsed) const;

 private:
  using Clock = std::chrono::steady_clock;
  void write(store::RunStatus state, double elapsed);
  void publish();

  const RunSettings& settings_;
  const Workload& workload_;
  RunState& state_;
  Checkpointer& checkpointer_;
  store::ResultFile& file_;
  const std::uint64_t items_total_;
  std::uint64_t finished_since_checkpoint_ = 0;
  Clock::time_point last_checkpoint_ = Clock::now(), last_write_ = last_checkpoint_,
                    last_publish_ = last_checkpoint_;
  PublishPacing pacing_;
  bool unpublished_ = false;
};

}  // namespace pbrfit::runtime
