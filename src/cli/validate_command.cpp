#include <cstdio>

#include "exit_on_error.hpp"
#include "pbrfit/cli/commands.hpp"
#include "pbrfit/core/error.hpp"
#include "pbrfit/jobs/job_kinds.hpp"

namespace pbrfit::cli {

int validate_command(const std::string& job_file) {
  return exit_on_error([&] {
    const auto job = spec::load_job_file(job_file, jobs::kind_catalogue());
    const auto workload = jobs::make_workload(job);
    std::printf("%s: ok: %s job '%s', %llu work items in %u stage%s, result %s\n", job_file.c_str(),
                job.kind.c_str(), job.name.c_str(), static_cast<unsigned long long>(workload->total_items()),
                workload->stage_count(), workload->stage_count() == 1 ? "" : "s", job.output.c_str());
    return exit_success;
  });
}

}  // namespace pbrfit::cli
