#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <fstream>
#include <string>

#include "exit_on_error.hpp"
#include "summary_reading.hpp"
#include "pbrfit/cli/commands.hpp"
#include "pbrfit/core/error.hpp"
#include "pbrfit/store/checkpoint_file.hpp"
#include "pbrfit/store/result_file.hpp"

namespace pbrfit::cli {

namespace {

// A process that is gone, or dead and waiting to be reaped (state Z), is not writing.
bool process_is_gone(std::int64_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  if (!stat) return kill(pid_t(pid), 0) != 0 && errno == ESRCH;
  std::string line;
  std::getline(stat, line);
  const auto end_of_name = line.rfind(')');
  return end_of_name != std::string::npos && end_of_name + 2 < line.size() && line[end_of_name + 2] == 'Z';
}

bool writer_is_gone(const store::ResultSummary& s) {
  if (s.writer_host != store::host_name() || s.writer_pid <= 0) return false;  // cannot tell from here
  return process_is_gone(s.writer_pid);
}

std::string state_of(const store::ResultSummary& s, const std::string& path) {
  if (s.state != store::RunStatus::running || !writer_is_gone(s)) return store::run_status_name(s.state);
  const bool resumable = access(store::checkpoint_path_for(path).c_str(), R_OK) == 0;
  return resumable ? "interrupted (the job stopped without saying so; its checkpoint can be resumed)"
                   : "interrupted (the job stopped without saying so and left no checkpoint)";
}

}  // namespace

int status_command(const std::string& result_file) {
  return exit_on_error([&] {
    const auto s = read_summary_or_explain(result_file);
    const double percent = s.items_total ? 100.0 * double(s.items_done) / double(s.items_total) : 0.0;
    std::printf("result:    %s\n", result_file.c_str());
    std::printf("job:       %s (%s), %lld rank%s, seed %llu\n", s.job_name.c_str(), s.job_kind.c_str(),
                static_cast<long long>(s.ranks), s.ranks == 1 ? "" : "s", static_cast<unsigned long long>(s.seed));
    std::printf("state:     %s\n", state_of(s, result_file).c_str());
    if (!s.scheduler_job.empty()) std::printf("scheduler: %s\n", s.scheduler_job.c_str());
    std::printf("progress:  %llu of %llu work items (%.1f%%)\n", static_cast<unsigned long long>(s.items_done),
                static_cast<unsigned long long>(s.items_total), percent);
    std::printf("elapsed:   %.1f s (started %s%s%s)\n", s.elapsed_seconds, s.started_utc.c_str(),
                s.finished_utc.empty() ? "" : ", finished ", s.finished_utc.c_str());
    std::printf("headline:  %s\n", s.headline.c_str());
    return exit_success;
  });
}

}  // namespace pbrfit::cli
