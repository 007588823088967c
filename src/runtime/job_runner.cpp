#include "pbrfit/runtime/job_runner.hpp"

#include <spdlog/spdlog.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>

#include "checkpointer.hpp"
#include "coordinator.hpp"
#include "persistence.hpp"
#include "existing_output.hpp"
#include "pbrfit/core/error.hpp"
#include "pbrfit/runtime/stop_signal.hpp"
#include "pbrfit/store/block_journal.hpp"
#include "pbrfit/store/output_lock.hpp"
#include "remote_worker.hpp"
#include "resumption.hpp"

namespace pbrfit::runtime {

namespace {

constexpr int already_complete = -1;
constexpr int proceed = -2;

// What rank 0 has ready before any work: the files and the state to start from, or an exit code.
struct Preparation {
  int code = proceed;
  std::unique_ptr<store::BlockCodec> codec = {};
  std::unique_ptr<RunState> state = {};
  std::unique_ptr<store::ResultFile> file = {};
  std::optional<Checkpointer> checkpointer = {};
  std::unique_ptr<store::OutputLock> lock = {};
  double elapsed_before = 0.0;
};

std::string scheduler_job() {
  const char* id = std::getenv("SLURM_JOB_ID");
  if (!id) return "";
  const char* restart = std::getenv("SLURM_RESTART_COUNT");
  return std::string("slurm job ") + id + ", restart " + (restart ? restart : "0");
}

std::unique_ptr<store::ResultFile> create_result_file(const MpiSession& mpi, const Workload& workload,
                                                      const RunSettings& s) {
  store::RunInfo info{s.job_name, s.job_kind, s.job_text, s.seed, mpi.size(), s.threads, store::utc_now_iso8601(),
                      scheduler_job()};
  return std::make_unique<store::ResultFile>(s.output, workload.layout(), info);
}

// Everything is checked (checkpoint and journal in full) before the result file is replaced.
void resume_from(Preparation& p, store::CheckpointReading checkpoint, const MpiSession& mpi,
                 const Workload& workload, const RunSettings& s) {
  const auto journal = store::journal_path_for(s.output);
  check_checkpoint(store::checkpoint_path_for(s.output), checkpoint.state, workload, *p.codec);
  store::replay_block_journal(journal, s.job_text, *p.codec, checkpoint.state.journal_length, [](store::Block) {});
  if (checkpoint.torn_tail) spdlog::warn("the last checkpoint was cut short; continuing from the one before it");
  const std::uint64_t journal_length = checkpoint.state.journal_length;
  p.elapsed_before = checkpoint.state.elapsed_seconds;
  p.state = std::make_unique<RunState>(workload, *p.codec, std::move(checkpoint.state));
  p.file = create_result_file(mpi, workload, s);
  store::Progress progress{store::RunStatus::running, p.state->items_done(), workload.total_items(), p.elapsed_before,
                           workload.headline(p.state->summary()), ""};
  rebuild_result_file(*p.file, journal, s.job_text, *p.codec, journal_length, progress);
  p.checkpointer = Checkpointer::resume(s.output, s.job_text, journal_length, checkpoint.valid_length);
}

void create_output_directory(const std::string& output) {
  const auto parent = std::filesystem::path(output).parent_path();
  std::error_code error;
  if (!parent.empty()) std::filesystem::create_directories(parent, error);
  if (error) throw RunError("cannot create the directory " + parent.string() + ": " + error.message());
}

Preparation prepare(const MpiSession& mpi, const Workload& workload, const RunSettings& s) {
  Preparation p;
  create_output_directory(s.output);
  p.lock = std::make_unique<store::OutputLock>(s.output);
  auto existing = inspect_existing_output(s);
  if (existing.complete) {
    spdlog::info("{} is already complete; nothing to do", s.output);
    p.code = already_complete;
    return p;
  }
  p.codec = std::make_unique<store::BlockCodec>(workload.layout());
  if (existing.checkpoint) {
    resume_from(p, std::move(*existing.checkpoint), mpi, workload, s);
    return p;
  }
  p.state = std::make_unique<RunState>(workload, *p.codec);
  p.file = create_result_file(mpi, workload, s);
  p.checkpointer = Checkpointer::start(s.output, s.job_text, *p.state);
  if (s.resume) spdlog::info("no checkpoint to resume from: starting from the beginning");
  if (existing.discards_checkpoint)
    spdlog::warn("starting over: the existing checkpoint was discarded (use --resume to continue from one)");
  return p;
}

int exit_code_of(Outcome outcome) {
  switch (outcome) {
    case Outcome::complete: return exit_success;
    case Outcome::interrupted:
    case Outcome::lost_rank: return exit_interrupted;
    default: return exit_run_failure;
  }
}

int coordinate(MpiSession& mpi, const Workload& workload, const RunSettings& s, Preparation& p,
               std::vector<int> threads) {
  Persistence persistence(s, workload, *p.state, *p.checkpointer, *p.file);
  Coordinator coordinator(mpi, workload, s, *p.state, persistence, std::move(threads), p.elapsed_before);
  const Outcome outcome = coordinator.run();
  if (outcome == Outcome::interrupted || outcome == Outcome::lost_rank)
    spdlog::warn("interrupted: checkpoint saved to {}; continue with: pbrfit run <job> --resume",
                 store::checkpoint_path_for(s.output));
  if (outcome == Outcome::complete) {
    p.lock->remove_file();
    spdlog::info("result: {}", s.output);
  }
  const int code = exit_code_of(outcome);
  if (!coordinator.say_farewell(code)) mpi.leave_without_finalize();
  return code;
}

Preparation prepare_reporting(const MpiSession& mpi, const Workload& workload, const RunSettings& settings) {
  try {
    return prepare(mpi, workload, settings);
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return Preparation{exit_invalid_input};
  } catch (const std::exception& e) {
    spdlog::error("cannot start the job: {}", e.what());
    return Preparation{exit_run_failure};
  }
}

}  // namespace

int run_workload(MpiSession& mpi, const Workload& workload, const RunSettings& settings) {
  install_stop_handlers();
  Preparation preparation;
  if (mpi.coordinator()) preparation = prepare_reporting(mpi, workload, settings);
  const int decision = mpi.broadcast_from_coordinator(preparation.code);
  if (decision == already_complete) return exit_success;
  if (decision != proceed) return decision;
  std::vector<int> threads = mpi.gather_to_coordinator(settings.threads);
  if (mpi.coordinator()) return coordinate(mpi, workload, settings, preparation, std::move(threads));
  const WorkerEnd end = serve_as_worker(mpi, workload, settings);
  if (end.coordinator_lost) mpi.leave_without_finalize();
  return end.exit_code;
}

}  // namespace pbrfit::runtime
