#include "pbrfit/runtime/job_runner.hpp"

#include <spdlog/spdlog.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>

#include "coordinator.hpp"
#include "pbrfit/core/error.hpp"
#include "pbrfit/runtime/stop_signal.hpp"
#include "remote_worker.hpp"

namespace pbrfit::runtime {

namespace {

constexpr int already_complete = -1;
constexpr int proceed = -2;

// What rank 0 decided before any work: go on (with what was resumed), or end with an exit code.
struct Preparation {
  int code = proceed;
  store::Checkpoint resumed;
  std::unique_ptr<store::ResultFile> file;
};

std::optional<store::Checkpoint> existing_checkpoint(const RunSettings& s) {
  const auto path = store::checkpoint_path_for(s.output);
  if (!std::filesystem::exists(path)) return std::nullopt;
  if (s.resume) return store::read_checkpoint(path);
  try {
    return store::read_checkpoint(path);
  } catch (const InputError& e) {
    spdlog::warn("ignoring an unreadable checkpoint (not resuming): {}", e.what());
    return std::nullopt;
  }
}

// Refuses to touch a checkpoint or result that belongs to a different job text, unless forced.
std::optional<store::Checkpoint> usable_checkpoint(const RunSettings& s) {
  auto checkpoint = existing_checkpoint(s);
  if (!checkpoint) return std::nullopt;
  const auto path = store::checkpoint_path_for(s.output);
  if (checkpoint->job_text != s.job_text) {
    if (!s.force)
      throw InputError({path}, "this checkpoint was written by a different job text; run the job file it came "
                               "from, or use --force to discard it");
    spdlog::warn("--force: discarding the checkpoint of a different job text: {}", path);
    return std::nullopt;
  }
  if (!s.resume) {
    spdlog::warn("starting over: the existing checkpoint is discarded (use --resume to continue from it)");
    return std::nullopt;
  }
  return checkpoint;
}

// The summary of an existing result file; nullopt when there is none or it cannot be read (a run killed
// while flushing can leave it so; its checkpoint, if any, rebuilds it).
std::optional<store::ResultSummary> existing_result(const RunSettings& s, bool have_checkpoint) {
  if (!std::filesystem::exists(s.output)) return std::nullopt;
  try {
    return store::read_result_summary(s.output);
  } catch (const InputError&) {
    if (have_checkpoint || s.force) return std::nullopt;
    throw InputError({s.output}, "exists but is not a readable pbrfit result; use --force to overwrite it");
  }
}

// Whether the output already holds this job's complete result; refuses another job text's result.
bool result_is_complete(const RunSettings& s, bool have_checkpoint) {
  const auto summary = existing_result(s, have_checkpoint);
  if (!summary) return false;
  if (summary->job_yaml != s.job_text) {
    if (!s.force)
      throw InputError({s.output}, "holds the result of a different job text (job '" + summary->job_name +
                                       "'); use --force to overwrite it or --output to write elsewhere");
    spdlog::warn("--force: overwriting the result of a different job text: {}", s.output);
    return false;
  }
  return summary->state == "complete";
}

std::string scheduler_job() {
  const char* id = std::getenv("SLURM_JOB_ID");
  if (!id) return "";
  const char* restart = std::getenv("SLURM_RESTART_COUNT");
  return std::string("slurm job ") + id + ", restart " + (restart ? restart : "0");
}

Preparation prepare(const MpiSession& mpi, const Workload& workload, const RunSettings& s) {
  Preparation p;
  auto checkpoint = usable_checkpoint(s);
  if (result_is_complete(s, checkpoint.has_value()) && s.resume && !checkpoint) {
    spdlog::info("{} is already complete; nothing to do", s.output);
    p.code = already_complete;
    return p;
  }
  if (checkpoint) p.resumed = std::move(*checkpoint);
  if (s.resume && p.resumed.results.empty()) spdlog::info("no checkpoint to resume from: starting from the beginning");
  p.resumed.job_text = s.job_text;
  const auto parent = std::filesystem::path(s.output).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  store::RunInfo info{s.job_name, s.job_kind, s.job_text, s.seed, mpi.size(), store::utc_now_iso8601(),
                      scheduler_job()};
  p.file = std::make_unique<store::ResultFile>(s.output, workload.layout(), info);
  return p;
}

int exit_code_of(Outcome outcome) {
  switch (outcome) {
    case Outcome::complete: return exit_success;
    case Outcome::interrupted: return exit_interrupted;
    default: return exit_run_failure;
  }
}

int coordinate(const MpiSession& mpi, const Workload& workload, const RunSettings& s, Preparation& p) {
  Coordinator coordinator(mpi, workload, s, std::move(p.resumed), *p.file);
  const Outcome outcome = coordinator.run();
  const auto checkpoint = store::checkpoint_path_for(s.output);
  if (outcome == Outcome::interrupted)
    spdlog::warn("interrupted: checkpoint saved to {}; continue with: pbrfit run <job> --resume", checkpoint);
  if (outcome == Outcome::complete) spdlog::info("result: {}", s.output);
  return exit_code_of(outcome);
}

}  // namespace

int run_workload(const MpiSession& mpi, const Workload& workload, const RunSettings& settings) {
  install_stop_handlers();
  Preparation preparation;
  if (mpi.coordinator()) {
    try {
      preparation = prepare(mpi, workload, settings);
    } catch (const InputError& e) {
      std::fprintf(stderr, "%s\n", e.what());
      preparation.code = exit_invalid_input;
    } catch (const std::exception& e) {
      spdlog::error("cannot start the job: {}", e.what());
      preparation.code = exit_run_failure;
    }
  }
  const int decision = mpi.broadcast_from_coordinator(preparation.code);
  if (decision == already_complete) return exit_success;
  if (decision != proceed) return decision;

  int code = exit_success;
  if (mpi.coordinator()) {
    code = coordinate(mpi, workload, settings, preparation);
  } else {
    serve_as_worker(workload);
  }
  return mpi.broadcast_from_coordinator(code);
}

}  // namespace pbrfit::runtime
