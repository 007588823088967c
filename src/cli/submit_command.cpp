#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "exit_on_error.hpp"
#include "pbrfit/cli/commands.hpp"
#include "pbrfit/core/error.hpp"
#include "pbrfit/store/share_directory.hpp"
#include "pbrfit/jobs/job_kinds.hpp"
#include "pbrfit/spec/job_spec.hpp"
#include "pbrfit/store/atomic_file.hpp"
#include "pbrfit/submit/batch_script.hpp"
#include "pbrfit/submit/sbatch.hpp"

namespace pbrfit::cli {

namespace {

std::string read_text(const std::string& path) {
  const Bytes bytes = store::read_whole_file(path, std::uint64_t(1) << 20);
  return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

submit::ResourceOverrides overrides_of(const SubmitOptions& options) {
  return {options.ranks, options.threads, options.time_limit, options.partition, options.account};
}

// Validates one job, renders its script and submits it (or prints it for --dry-run).
void submit_one(const std::string& job_file, const SubmitOptions& options, const std::string& template_path,
                const std::string& template_text) {
  const auto job = spec::load_job_file(job_file, jobs::kind_catalogue());
  jobs::make_workload(job);
  const auto batch = submit::batch_job_for(job, overrides_of(options),
                                           std::filesystem::read_symlink("/proc/self/exe").string(),
                                           std::filesystem::current_path().string());
  const std::string script = submit::render_batch_script(batch, template_text, template_path);
  if (options.dry_run) {
    std::printf("%s", script.c_str());
    return;
  }
  std::filesystem::create_directories(std::filesystem::path(batch.script).parent_path());
  store::replace_file_atomically(batch.script, std::as_bytes(std::span(script.data(), script.size())));
  const std::string id = submit::run_sbatch(batch.script);
  std::string log = batch.log;
  if (const auto at = log.find("%j"); at != std::string::npos) log.replace(at, 2, id);
  std::printf("submitted %s as Slurm job %s (%d rank%s x %d thread%s, time limit %s)\n  result: %s\n  log:    %s\n  script: %s\n",
              job_file.c_str(), id.c_str(), batch.ranks, batch.ranks == 1 ? "" : "s", batch.threads,
              batch.threads == 1 ? "" : "s", batch.time_limit.c_str(),
              batch.output.c_str(), log.c_str(), batch.script.c_str());
  std::printf("  watch:  pbrfit status %s\n", batch.output.c_str());
}

}  // namespace

int submit_command(const SubmitOptions& options) {
  int worst = exit_success;
  for (const auto& job_file : options.job_files) {
    const int code = exit_on_error([&] {
      const std::string template_path =
          options.template_file.empty() ? store::share_directory() + "/sbatch.template" : options.template_file;
      submit_one(job_file, options, template_path, read_text(template_path));
      return int(exit_success);
    });
    worst = std::max(worst, code);
  }
  return worst;
}

}  // namespace pbrfit::cli
