#include "existing_output.hpp"

#include <spdlog/spdlog.h>

#include <filesystem>

#include "pbrfit/core/error.hpp"
#include "pbrfit/store/result_file.hpp"

namespace pbrfit::runtime {

namespace {

std::optional<store::CheckpointReading> existing_checkpoint(const RunSettings& s) {
  const auto path = store::checkpoint_path_for(s.output);
  std::error_code error;
  if (!std::filesystem::exists(std::filesystem::symlink_status(path, error))) return std::nullopt;
  if (s.resume) return store::read_checkpoint(path);
  try {
    return store::read_checkpoint(path);
  } catch (const InputError& e) {
    spdlog::warn("ignoring an unreadable checkpoint (not resuming): {}", e.what());
    return std::nullopt;
  }
}

// The summary of an existing result file; nullopt when there is none or it cannot be read (a run killed
// while writing it can leave it so; its checkpoint, if any, rebuilds it).
std::optional<store::ResultSummary> existing_result(const RunSettings& s, bool have_checkpoint) {
  std::error_code error;
  if (!std::filesystem::exists(std::filesystem::symlink_status(s.output, error))) return std::nullopt;
  try {
    return store::read_result_summary(s.output);
  } catch (const InputError&) {
    if (have_checkpoint || s.force) return std::nullopt;
    throw InputError({s.output}, "exists but is not a readable pbrfit result; use --force to overwrite it");
  }
}

// pbrfit reads and replaces only regular files: a FIFO, device or directory at one of its paths would
// block a read or be replaced.
void require_regular_or_absent(const std::string& path) {
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (error || status.type() == std::filesystem::file_type::not_found) return;
  if (status.type() == std::filesystem::file_type::directory) throw InputError({path}, "is a directory, not a file");
  if (status.type() != std::filesystem::file_type::regular)
    throw InputError({path}, "is not a regular file (pbrfit reads and writes only regular files)");
}

}  // namespace

ExistingOutput inspect_existing_output(const RunSettings& s) {
  for (const auto& path : {s.output, store::checkpoint_path_for(s.output), store::journal_path_for(s.output),
                           s.output + ".writing"})
    require_regular_or_absent(path);
  ExistingOutput found;
  auto checkpoint = existing_checkpoint(s);
  if (checkpoint && checkpoint->state.job_text != s.job_text) {
    if (!s.force)
      throw InputError({store::checkpoint_path_for(s.output)},
                       "this checkpoint was written by a different job text; run the job file it came from, or use "
                       "--force to discard it");
    spdlog::warn("--force: discarding the checkpoint of a different job text: {}", store::checkpoint_path_for(s.output));
    checkpoint.reset();
  }
  const auto result = existing_result(s, checkpoint.has_value());
  if (result && result->job_yaml != s.job_text && !s.force)
    throw InputError({s.output}, "holds the result of a different job text (job '" + result->job_name +
                                     "'); use --force to overwrite it or --output to write elsewhere");
  if (result && result->job_yaml != s.job_text)
    spdlog::warn("--force: overwriting the result of a different job text: {}", s.output);
  const bool same_job = result && result->job_yaml == s.job_text;
  found.complete = s.resume && !checkpoint && same_job && result->state == store::RunStatus::complete;
  found.discards_checkpoint = checkpoint && !s.resume;
  if (s.resume) found.checkpoint = std::move(checkpoint);
  return found;
}

}  // namespace pbrfit::runtime
